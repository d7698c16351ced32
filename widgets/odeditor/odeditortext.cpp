#include "odeditormodel.h"

#include <QCoreApplication>
#include <QLocale>

namespace db::widgets::odtext {

namespace {
bool isScaled(const ObjectDef &def)
{
    return datatype::isNumeric(def.type) && def.type != DataType::Boolean
        && (def.factor != 1.0 || def.offset != 0.0);
}

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::widgets::OdEditorModel)
};

bool inRange(quint16 index, quint16 first, quint16 last)
{
    return index >= first && index <= last;
}
} // namespace

// Words made of bits (6040h, 6041h, 1002h, ...) and identifiers (1000h device type, 1018h
// identity, COB-IDs, PDO mapping entries) read better in hex, whatever the toggle says.
bool isShownInHex(const ObjectDef &def)
{
    if (!datatype::isUnsignedInteger(def.type))
        return false;
    const quint16 i = def.address.index;
    const quint8 sub = def.address.sub;
    if (!def.bitFields.isEmpty())
        return true;
    if (sub == 0
        && (i == 0x6040 || i == 0x6041 || i == 0x60FD || i == 0x1000 || i == 0x1001 || i == 0x1002
            || i == 0x1005 || i == 0x1012 || i == 0x1014 || i == 0x603F))
        return true;
    if (sub == 0)
        return false; // the number of entries of a record
    return i == 0x1018 // vendor, product, revision, serial
        || (sub == 1 && (inRange(i, 0x1400, 0x15FF) || inRange(i, 0x1800, 0x19FF))) // COB-IDs
        || inRange(i, 0x1600, 0x17FF) || inRange(i, 0x1A00, 0x1BFF); // mapping entries
}

namespace {
bool isBitWord(const ObjectDef &def)
{
    return isShownInHex(def);
}

QString number(const ObjectDef &def, const QVariant &raw, bool hex)
{
    if ((hex || isBitWord(def)) && datatype::isInteger(def.type))
        return codec::toText(def.type, raw, codec::TextFormat::Hex);
    // Fixed-point parameters show exactly their decimals ("10.00"), as the drive's lists do.
    if (isScaled(def) && def.decimals >= 0)
        return QString::number(codec::toPhysical(raw, def.factor, def.offset), 'f', def.decimals);
    if (isScaled(def))
        return QString::number(codec::toPhysical(raw, def.factor, def.offset), 'g', 10);
    return codec::toText(def.type, raw, codec::TextFormat::Decimal);
}
} // namespace

QString display(const ObjectDef &def, const QVariant &raw, bool hex, bool withUnit, bool english)
{
    if (!raw.isValid())
        return {};
    if (def.type == DataType::VisibleString || def.type == DataType::UnicodeString)
        return raw.toString();
    QString text = number(def, raw, hex);
    if (datatype::isInteger(def.type) && !def.enumeration.isEmpty()) {
        const auto it = def.enumeration.constFind(raw.toLongLong());
        if (it != def.enumeration.cend())
            text += QStringLiteral(" (%1)").arg(english ? *it : def.enumText(it.key()));
    }
    const bool shownHex = (hex || isBitWord(def)) && !isScaled(def);
    if (withUnit && !def.unit.isEmpty() && datatype::isNumeric(def.type) && !shownHex)
        text += QLatin1Char(' ') + (english ? def.unit : def.displayUnit());
    return text;
}

QString edit(const ObjectDef &def, const QVariant &raw, bool hex)
{
    if (!raw.isValid())
        return {};
    if (def.type == DataType::VisibleString || def.type == DataType::UnicodeString)
        return raw.toString();
    return number(def, raw, hex);
}

Result<QVariant> parse(const ObjectDef &def, const QString &text, const AddressFormat &format)
{
    if (!def.writable()) {
        return Error(Error::Kind::AccessDenied,
                     Tr::tr("%1 is %2 and cannot be written")
                         .arg(format.format(def.address), access::name(def.access)));
    }
    const QString t = text.trimmed();
    if (t.isEmpty() && datatype::isNumeric(def.type))
        return Error(Error::Kind::InvalidArgument, Tr::tr("enter a value"));
    // Physical input for scaled objects, unless the user typed a raw hex pattern.
    if (isScaled(def) && !t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
        bool ok = false;
        const double physical = QLocale::c().toDouble(t, &ok);
        if (!ok) {
            return Error(Error::Kind::InvalidArgument,
                         Tr::tr("'%1' is not a number").arg(t.left(40)));
        }
        auto raw = codec::fromPhysical(def.type, physical, def.factor, def.offset);
        if (!raw)
            return raw.error();
        return def.validate(raw.value(), format);
    }
    return def.parseText(t, format);
}

QString limits(const ObjectDef &def, bool hex)
{
    if (!def.minimum.isValid() && !def.maximum.isValid())
        return {};
    const QString low = def.minimum.isValid() ? number(def, def.minimum, hex) : QString();
    const QString high = def.maximum.isValid() ? number(def, def.maximum, hex) : QString();
    return QStringLiteral("%1 … %2").arg(low, high);
}

} // namespace db::widgets::odtext
