#include "parameterset.h"
#include "core/filereader.h"
#include "core/filewriter.h"
#include "core/printable.h"

#include <QFile>
#include <QSaveFile>

#include <QCoreApplication>
#include <algorithm>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

namespace {

constexpr auto kMagic = "# drivebench parameter set";

bool lessByAddress(const ParameterEntry &e, ObjectAddress a)
{
    return e.address < a;
}

// Strings go in double quotes with C-style escapes for the characters that would break a line
// or the quoting, and \xNN / \uNNNN for the other control characters, which would act on a
// terminal showing the file; everything else (UTF-8) is written as it is.
QString quoted(const QString &text)
{
    QString out;
    out.reserve(text.size() + 2);
    out += QLatin1Char('"');
    for (const QChar c : text) {
        switch (c.unicode()) {
        case '"':
            out += QLatin1String("\\\"");
            break;
        case '\\':
            out += QLatin1String("\\\\");
            break;
        case '\n':
            out += QLatin1String("\\n");
            break;
        case '\r':
            out += QLatin1String("\\r");
            break;
        case '\t':
            out += QLatin1String("\\t");
            break;
        default:
            if (c.isSurrogate() || isPrintable(QStringView(&c, 1)))
                out += c;
            else if (c.unicode() < 0x80)
                out += QStringLiteral("\\x%1").arg(c.unicode(), 2, 16, QLatin1Char('0'));
            else
                out += QStringLiteral("\\u%1").arg(c.unicode(), 4, 16, QLatin1Char('0'));
        }
    }
    out += QLatin1Char('"');
    return out;
}

QString hex32(quint32 v)
{
    return QStringLiteral("0x")
        + QString::number(v, 16).toUpper().rightJustified(8, QLatin1Char('0'));
}

// A "# " comment line (a NUL or CR a device sent stays visible and on the line): at most this
// long.
constexpr qsizetype kMaxCommentChars = 400;

bool isTextType(DataType type)
{
    return datatype::isVariableLength(type);
}

} // namespace

const ParameterEntry *ParameterSet::find(ObjectAddress address) const
{
    const auto it = std::lower_bound(m_entries.cbegin(), m_entries.cend(), address, lessByAddress);
    return it != m_entries.cend() && it->address == address ? &*it : nullptr;
}

QList<ObjectAddress> ParameterSet::addresses() const
{
    QList<ObjectAddress> out;
    out.reserve(m_entries.size());
    for (const ParameterEntry &e : m_entries)
        out.append(e.address);
    return out;
}

QMap<ObjectAddress, QVariant> ParameterSet::values() const
{
    QMap<ObjectAddress, QVariant> out;
    for (const ParameterEntry &e : m_entries)
        out.insert(e.address, e.raw);
    return out;
}

void ParameterSet::insert(const ParameterEntry &entry)
{
    const auto it =
        std::lower_bound(m_entries.begin(), m_entries.end(), entry.address, lessByAddress);
    if (it != m_entries.end() && it->address == entry.address)
        *it = entry;
    else
        m_entries.insert(it, entry);
}

bool ParameterSet::remove(ObjectAddress address)
{
    const auto it = std::lower_bound(m_entries.begin(), m_entries.end(), address, lessByAddress);
    if (it == m_entries.end() || it->address != address)
        return false;
    m_entries.erase(it);
    return true;
}

QString ParameterSet::identityNumber(quint32 value)
{
    return QStringLiteral("0x%1").arg(
        QStringLiteral("%1").arg(value, 8, 16, QLatin1Char('0')).toUpper());
}

QByteArray ParameterSet::serialize(const QStringList &comments) const
{
    QString text;
    auto line = [&text](const QString &l) {
        text += l;
        text += QLatin1Char('\n');
    };
    line(QString::fromLatin1(kMagic));
    line(QStringLiteral("format %1").arg(kFormatVersion));
    // CANopen sets are written as before the line existed, so that older readers take them.
    if (addressFormat->key() != AddressFormat::canopen().key())
        line(QStringLiteral("addresses %1").arg(addressFormat->key()));
    const QString unknown = QStringLiteral("unknown");
    line(QStringLiteral("vendor %1 %2")
             .arg(vendorIdKnown ? hex32(identity.vendorId) : unknown, quoted(identity.vendorName)));
    line(QStringLiteral("product %1 %2")
             .arg(productCodeKnown ? hex32(identity.productCode) : unknown,
                  quoted(identity.productName)));
    line(QStringLiteral("revision %1").arg(quoted(identity.revision)));
    if (!serialNumber.isEmpty())
        line(QStringLiteral("serial %1").arg(quoted(serialNumber)));
    line(QStringLiteral("description %1 %2")
             .arg(quoted(identity.descriptionFile), quoted(identity.descriptionVersion)));
    line(QStringLiteral("source %1").arg(quoted(source)));
    if (created.isValid())
        line(QStringLiteral("created %1").arg(created.toUTC().toString(Qt::ISODateWithMs)));
    for (const QString &comment : comments)
        line(QStringLiteral("# ") + oneLine(comment, kMaxCommentChars));
    line(QStringLiteral("entries %1").arg(m_entries.size()));
    for (const ParameterEntry &e : m_entries) {
        const QString value = codec::toText(e.type, e.raw);
        line(QStringLiteral("%1 %2 %3 %4 %5")
                 .arg(addressFormat->format(e.address), quoted(e.name), datatype::name(e.type),
                      isTextType(e.type) ? quoted(value) : value, quoted(e.unit)));
    }
    line(QStringLiteral("end"));
    return text.toUtf8();
}

Result<void> ParameterSet::save(const QString &path, const QStringList &comments) const
{
    db::files::removeStaleTemporaries(path); // what a killed writer left
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return Error(Error::Kind::Io, Tr::tr("cannot write %1: %2").arg(path, file.errorString()));
    const QByteArray bytes = serialize(comments);
    if (file.write(bytes) != bytes.size() || !file.commit())
        return Error(Error::Kind::Io, Tr::tr("cannot write %1: %2").arg(path, file.errorString()));
    return {};
}

Result<ParameterSet> ParameterSet::load(const QString &path)
{
    const Result<QByteArray> bytes =
        files::readAll(path, files::kParameterSetLimit, Tr::tr("a parameter set"));
    if (!bytes)
        return bytes.error();
    return parse(*bytes, path);
}

ParameterSet ParameterSet::defaults(const ObjectDictionary &dictionary)
{
    ParameterSet set;
    set.identity = dictionary.identity;
    set.addressFormat = &dictionary.addressFormat();
    set.source = QStringLiteral("defaults");
    set.created = QDateTime::currentDateTimeUtc();
    for (const ObjectDef &def : dictionary.objects()) {
        if (!def.storable || !def.defaultValue.isValid())
            continue;
        const auto raw = codec::normalize(def.type, def.defaultValue);
        if (!raw)
            continue; // a description default outside its type is the description's problem
        set.insert({ def.address, def.name, def.type, raw.value(), def.unit });
    }
    return set;
}

} // namespace db
