#include "trigger.h"

#include "core/objectaddress.h"

#include <QCoreApplication>
#include <cmath>

namespace db::scope {

namespace {

struct KindName
{
    Trigger::Kind kind;
    const char *name;
    int levels; // numbers after the kind
};

constexpr KindName kKinds[] = {
    { Trigger::Kind::RisingEdge, "rising", 1 },   { Trigger::Kind::FallingEdge, "falling", 1 },
    { Trigger::Kind::LevelAbove, "above", 1 },    { Trigger::Kind::LevelBelow, "below", 1 },
    { Trigger::Kind::WindowInside, "inside", 2 }, { Trigger::Kind::WindowOutside, "outside", 2 },
};

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::scope::Trigger)
};

Error invalid(const QString &spec, const QString &why)
{
    return Error(Error::Kind::InvalidArgument,
                 Tr::tr("trigger '%1': %2 (expected CHANNEL,rising|falling|above|below,LEVEL or "
                        "CHANNEL,inside|outside,LOW,HIGH or CHANNEL,bitN,set|clear)")
                     .arg(spec, why));
}

} // namespace

QString Trigger::kindName(Kind kind)
{
    for (const KindName &k : kKinds) {
        if (k.kind == kind)
            return QString::fromLatin1(k.name);
    }
    return kind == Kind::BitSet ? QStringLiteral("set") : QStringLiteral("clear");
}

QString Trigger::conditionText() const
{
    switch (kind) {
    case Kind::BitSet:
    case Kind::BitClear:
        return QStringLiteral("bit%1,%2").arg(bit).arg(kindName(kind));
    case Kind::WindowInside:
    case Kind::WindowOutside:
        return QStringLiteral("%1,%2,%3")
            .arg(kindName(kind))
            .arg(level, 0, 'g', 17)
            .arg(level2, 0, 'g', 17);
    default:
        return QStringLiteral("%1,%2").arg(kindName(kind)).arg(level, 0, 'g', 17);
    }
}

Result<Trigger> Trigger::parse(const QString &spec, const QStringList &channelIds)
{
    return parse(spec, channelIds, Trigger());
}

Result<Trigger> Trigger::parse(const QString &spec, const QStringList &channelIds,
                               const Trigger &base, const AddressFormat &format)
{
    const QStringList parts = spec.trimmed().split(QLatin1Char(','));
    if (parts.size() < 2)
        return invalid(spec, Tr::tr("missing condition"));
    Trigger trigger = base;
    trigger.channel = int(channelIds.indexOf(parts[0].trimmed()));
    if (trigger.channel < 0) {
        const auto address = format.parse(parts[0].trimmed());
        if (!address)
            return invalid(spec, address.error().message());
        for (int i = 0; i < channelIds.size(); ++i) {
            const auto id = format.parse(channelIds[i]);
            if (id && *id == *address)
                trigger.channel = i;
        }
    }
    if (trigger.channel < 0)
        return invalid(spec,
                       Tr::tr("%1 is not one of the recorded channels").arg(parts[0].trimmed()));

    const QString kind = parts[1].trimmed().toLower();
    if (kind.startsWith(QLatin1String("bit"))) {
        bool ok = false;
        trigger.bit = kind.mid(3).toInt(&ok);
        if (!ok || trigger.bit < 0 || trigger.bit > 63)
            return invalid(spec, Tr::tr("bit number must be 0..63"));
        const QString state =
            parts.size() > 2 ? parts[2].trimmed().toLower() : QStringLiteral("set");
        if (parts.size() > 3 || (state != QLatin1String("set") && state != QLatin1String("clear")))
            return invalid(spec, Tr::tr("a bit trigger ends in 'set' or 'clear'"));
        trigger.kind = state == QLatin1String("set") ? Kind::BitSet : Kind::BitClear;
        return trigger;
    }
    for (const KindName &k : kKinds) {
        if (kind != QLatin1String(k.name))
            continue;
        if (parts.size() != 2 + k.levels)
            return invalid(spec,
                           QCoreApplication::translate("db::scope::Trigger",
                                                       "'%1' takes %n number(s)", nullptr, k.levels)
                               .arg(kind));
        double levels[2] = { 0, 0 };
        for (int i = 0; i < k.levels; ++i) {
            bool ok = false;
            levels[i] = parts[2 + i].trimmed().toDouble(&ok);
            if (!ok || !std::isfinite(levels[i]))
                return invalid(spec, Tr::tr("'%1' is not a number").arg(parts[2 + i].trimmed()));
        }
        if (k.levels == 2 && levels[0] > levels[1])
            return invalid(spec, Tr::tr("window low bound above the high bound"));
        trigger.kind = k.kind;
        trigger.level = levels[0];
        trigger.level2 = levels[1];
        return trigger;
    }
    return invalid(spec, Tr::tr("unknown condition '%1'").arg(kind));
}

TriggerDetector::TriggerDetector(const Trigger &trigger, double scale, double offset)
    : m_trigger(trigger)
    , m_scale(scale)
    , m_offset(offset)
{ }

bool TriggerDetector::condition(double raw, double shown) const
{
    using Kind = Trigger::Kind;
    switch (m_trigger.kind) {
    case Kind::RisingEdge:
        return m_hasPrevious && m_previous < m_trigger.level && shown >= m_trigger.level;
    case Kind::FallingEdge:
        return m_hasPrevious && m_previous > m_trigger.level && shown <= m_trigger.level;
    case Kind::LevelAbove:
        return shown > m_trigger.level;
    case Kind::LevelBelow:
        return shown < m_trigger.level;
    case Kind::WindowInside:
        return shown >= m_trigger.level && shown <= m_trigger.level2;
    case Kind::WindowOutside:
        return shown < m_trigger.level || shown > m_trigger.level2;
    case Kind::BitSet:
    case Kind::BitClear: {
        // Raw integers up to 2^53 are exact in a double; the bit is taken from the two's
        // complement of the integer so negative statuswords (e.g. int16) work too.
        const auto bits = quint64(qint64(std::llround(raw)));
        const bool set = (bits >> m_trigger.bit) & 1u;
        return m_trigger.kind == Kind::BitSet ? set : !set;
    }
    }
    return false;
}

bool TriggerDetector::feed(double raw)
{
    const double shown = raw * m_scale + m_offset;
    const bool fired = condition(raw, shown);
    m_previous = shown;
    m_hasPrevious = true;
    return fired;
}

} // namespace db::scope
