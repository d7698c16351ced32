#include "filereader.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::files)
};

QString megabytes(qint64 bytes)
{
    return QString::number(double(bytes) / double(db::files::kMiB), 'f',
                           bytes < 10 * db::files::kMiB ? 1 : 0);
}

} // namespace

namespace db::files {

Result<QByteArray> readAll(const QString &path, qint64 maxBytes, const QString &what)
{
    const QFileInfo info(path);
    if (info.isDir())
        return Error(Error::Kind::Io,
                     Tr::tr("cannot read %1: it is a folder, not a file").arg(path));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return Error(Error::Kind::Io, Tr::tr("cannot read %1: %2").arg(path, file.errorString()));
    // The size as opened (a regular file); pipes and devices report 0 and are read up to the
    // limit below.
    if (file.size() > maxBytes)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1 is %2 MB, more than the %3 MB %4 may have: is it the right file?")
                         .arg(path, megabytes(file.size()), megabytes(maxBytes), what));
    QByteArray bytes = file.read(maxBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return Error(Error::Kind::Io, Tr::tr("cannot read %1: %2").arg(path, file.errorString()));
    if (bytes.size() > maxBytes)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1 is more than the %2 MB %3 may have: is it the right file?")
                         .arg(path, megabytes(maxBytes), what));
    return bytes;
}

QString textPosition(const QByteArray &text, qint64 offset)
{
    offset = qBound(qint64(0), offset, qint64(text.size()));
    const qsizetype lineStart = offset == 0 ? 0 : text.lastIndexOf('\n', offset - 1) + 1;
    const qint64 line = text.left(lineStart).count('\n') + 1;
    const qint64 column = QString::fromUtf8(text.mid(lineStart, offset - lineStart)).size() + 1;
    return Tr::tr("line %1, column %2").arg(line).arg(column);
}

} // namespace db::files
