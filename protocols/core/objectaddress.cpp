#include "objectaddress.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::core)
};
} // namespace

namespace db {

QString ObjectAddress::toString() const
{
    return QStringLiteral("%1:%2").arg(index, 4, 16, QLatin1Char('0')).arg(sub, 0, 16).toUpper();
}

Result<ObjectAddress> ObjectAddress::parse(const QString &text)
{
    static const QRegularExpression re(
        QStringLiteral(
            R"(^\s*(?:0x)?([0-9a-f]{1,4})h?\s*(?:(?:[:.,]|sub)\s*(?:0x)?([0-9a-f]{1,2})h?)?\s*$)"),
        QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(text);
    if (!m.hasMatch()) {
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("'%1' is not an object address; write INDEX:SUB in hex, "
                            "e.g. 6041:0")
                         .arg(text));
    }
    const quint16 index = static_cast<quint16>(m.captured(1).toUInt(nullptr, 16));
    const quint8 sub =
        m.captured(2).isEmpty() ? 0 : static_cast<quint8>(m.captured(2).toUInt(nullptr, 16));
    return ObjectAddress(index, sub);
}

} // namespace db
