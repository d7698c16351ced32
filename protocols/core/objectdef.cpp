#include "objectdef.h"

#include <QCoreApplication>

#include <cmath>

namespace db {

QString textLanguage()
{
    // Each translation says which language it is, the way Qt's own translations say their layout
    // direction (QT_LAYOUT_DIRECTION): no state to keep in step with the installed translators.
    const QString code = QCoreApplication::translate(
        "db::TextLanguage", "en",
        "The code of this translation's language (de, fr, ...): device descriptions show the "
        "names they have in it.");
    return code.isEmpty() ? QStringLiteral("en") : code;
}

QString localText(const QString &english, const LocalTexts &local)
{
    if (local.isEmpty())
        return english;
    const QString text = local.value(textLanguage());
    return text.isEmpty() ? english : text;
}

QString access::name(Access access)
{
    switch (access) {
    case Access::ReadOnly:
        return QStringLiteral("ro");
    case Access::WriteOnly:
        return QStringLiteral("wo");
    case Access::ReadWrite:
        return QStringLiteral("rw");
    case Access::Const:
        return QStringLiteral("const");
    }
    return QStringLiteral("rw");
}

std::optional<Access> access::fromName(const QString &text)
{
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("ro") || t == QLatin1String("r"))
        return Access::ReadOnly;
    if (t == QLatin1String("wo") || t == QLatin1String("w"))
        return Access::WriteOnly;
    if (t == QLatin1String("rw") || t == QLatin1String("rww") || t == QLatin1String("rwr"))
        return Access::ReadWrite;
    if (t == QLatin1String("const"))
        return Access::Const;
    return std::nullopt;
}

Result<QVariant> ObjectDef::validate(const QVariant &value, const AddressFormat &format) const
{
    auto raw = codec::normalize(type, value);
    if (!raw)
        return raw.error().prefixed(format.format(address));
    if (auto limits = codec::checkLimits(type, raw.value(), minimum, maximum); !limits)
        return limits.error().prefixed(format.format(address));
    return raw;
}

QString ObjectDef::enumText(qlonglong value) const
{
    const auto it = enumeration.constFind(value);
    if (it == enumeration.cend())
        return {};
    return localText(*it, localEnumeration.value(value));
}

QMap<qlonglong, QString> ObjectDef::displayEnumeration() const
{
    if (localEnumeration.isEmpty())
        return enumeration;
    QMap<qlonglong, QString> shown;
    for (auto it = enumeration.cbegin(); it != enumeration.cend(); ++it)
        shown.insert(it.key(), localText(it.value(), localEnumeration.value(it.key())));
    return shown;
}

Result<QVariant> ObjectDef::parseText(const QString &text, const AddressFormat &format) const
{
    const QString t = text.trimmed();
    for (auto it = enumeration.cbegin(); it != enumeration.cend(); ++it) {
        if (it.value().compare(t, Qt::CaseInsensitive) == 0)
            return validate(QVariant::fromValue<qlonglong>(it.key()), format);
    }
    for (auto it = localEnumeration.cbegin(); it != localEnumeration.cend(); ++it) {
        for (const QString &local : it.value()) {
            if (local.compare(t, Qt::CaseInsensitive) == 0)
                return validate(QVariant::fromValue<qlonglong>(it.key()), format);
        }
    }
    if (decimals > 0 && datatype::isInteger(type)) {
        bool ok = false;
        const double physical = t.toDouble(&ok);
        if (!ok)
            return Error(Error::Kind::InvalidArgument,
                         QStringLiteral("'%1' is not a number").arg(text))
                .prefixed(format.format(address));
        const double scaled = (physical - offset) / factor;
        if (std::abs(scaled - std::round(scaled)) > 1e-6)
            return Error(Error::Kind::InvalidArgument,
                         QStringLiteral("%1 has more than %2 decimal places").arg(t).arg(decimals))
                .prefixed(format.format(address));
        auto raw = codec::fromPhysical(type, physical, factor, offset);
        if (!raw)
            return raw.error().prefixed(format.format(address));
        return validate(raw.value(), format);
    }
    auto raw = codec::fromText(type, text);
    if (!raw)
        return raw.error().prefixed(format.format(address));
    return validate(raw.value(), format);
}

namespace {
QString valueText(const ObjectDef &def, const QVariant &raw, codec::TextFormat format, bool local)
{
    if (!raw.isValid())
        return {};
    QString text = codec::toText(def.type, raw, format);
    if (datatype::isInteger(def.type) && !def.enumeration.isEmpty()) {
        const auto it = def.enumeration.constFind(raw.toLongLong());
        if (it != def.enumeration.cend())
            text += QStringLiteral(" (%1)").arg(local ? def.enumText(it.key()) : *it);
    } else if (def.decimals > 0 && datatype::isInteger(def.type)
               && format == codec::TextFormat::Decimal) {
        text = QString::number(codec::toPhysical(raw, def.factor, def.offset), 'f', def.decimals);
    } else if (datatype::isNumeric(def.type) && (def.factor != 1.0 || def.offset != 0.0)) {
        text = QString::number(codec::toPhysical(raw, def.factor, def.offset), 'g', 10);
    }
    if (!def.unit.isEmpty() && datatype::isNumeric(def.type)
        && format == codec::TextFormat::Decimal)
        text += QLatin1Char(' ') + (local ? def.displayUnit() : def.unit);
    return text;
}
} // namespace

QString ObjectDef::displayText(const QVariant &raw, codec::TextFormat format) const
{
    return valueText(*this, raw, format, false);
}

QString ObjectDef::localDisplayText(const QVariant &raw, codec::TextFormat format) const
{
    return valueText(*this, raw, format, true);
}

} // namespace db
