#include "addressformat.h"

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

namespace {

class CanopenFormat final : public AddressFormat
{
public:
    QString key() const override { return QStringLiteral("canopen"); }
    Result<ObjectAddress> parse(const QString &text) const override
    {
        return ObjectAddress::parse(text);
    }
    QString format(ObjectAddress address) const override { return address.toString(); }
    QString example() const override { return QStringLiteral("6041:0"); }
    QString indexName() const override { return Tr::tr("index"); }
    QString subName() const override { return Tr::tr("sub-index"); }
};

class ParameterFormat final : public AddressFormat
{
public:
    // Parameter numbers fit the 16-bit index; data sets 0-9 (0 = all, 1-4 EEPROM, 5-9 the RAM
    // copies of 0-4) fit the sub-index with room to spare, so 0-255 is accepted here and the
    // protocol refuses what it cannot send.
    // The key names the format in files and URIs: never translated.
    QString key() const override { return QStringLiteral("parameter"); }
    Result<ObjectAddress> parse(const QString &text) const override
    {
        static const QRegularExpression re(
            QStringLiteral(R"(^\s*([0-9]{1,5})\s*(?:[:.,]\s*([0-9]{1,3}))?\s*$)"));
        const auto m = re.match(text);
        if (!m.hasMatch()) {
            return Error(Error::Kind::InvalidArgument,
                         QCoreApplication::translate("db::AddressFormat",
                                                     "'%1' is not a parameter address; write "
                                                     "NUMBER:DATASET in decimal, e.g. 372:2 (a "
                                                     "number alone is data set 0)")
                             .arg(text));
        }
        const uint index = m.captured(1).toUInt();
        const uint sub = m.captured(2).isEmpty() ? 0 : m.captured(2).toUInt();
        if (index > 0xFFFF || sub > 0xFF) {
            return Error(Error::Kind::OutOfRange,
                         QCoreApplication::translate("db::AddressFormat",
                                                     "'%1' is not a parameter address: "
                                                     "NUMBER:DATASET takes a parameter number "
                                                     "of 0-65535 and a data set of 0-255, e.g. "
                                                     "372:2")
                             .arg(text));
        }
        return ObjectAddress(static_cast<quint16>(index), static_cast<quint8>(sub));
    }
    QString format(ObjectAddress address) const override
    {
        return QStringLiteral("%1:%2").arg(address.index).arg(address.sub);
    }
    QString example() const override { return QStringLiteral("372:2"); }
    QString indexName() const override { return Tr::tr("parameter"); }
    QString subName() const override { return Tr::tr("data set"); }
};

} // namespace

QString AddressFormat::formatIndex(quint16 index) const
{
    return format(ObjectAddress(index, 0)).section(QLatin1Char(':'), 0, 0);
}

const AddressFormat &AddressFormat::canopen()
{
    static const CanopenFormat format;
    return format;
}

const AddressFormat &AddressFormat::parameter()
{
    static const ParameterFormat format;
    return format;
}

const AddressFormat *AddressFormat::byKey(const QString &key)
{
    if (key == canopen().key())
        return &canopen();
    if (key == parameter().key())
        return &parameter();
    return nullptr;
}

} // namespace db
