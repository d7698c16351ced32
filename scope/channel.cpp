#include "channel.h"

#include "core/objectdictionary.h"

#include <algorithm>
#include <cmath>

namespace db::scope {

namespace {

// The decimal places of multiples of `factor` (0.01 -> 2, 2.5 -> 1, 1 -> 0); -1 when it has
// more than 9 (1/3).
int decimalsOf(double factor)
{
    double scaled = std::abs(factor);
    for (int d = 0; d <= 9; ++d, scaled *= 10) {
        if (std::abs(scaled - std::round(scaled)) <= 1e-9 * std::max(1.0, scaled))
            return d;
    }
    return -1;
}

} // namespace

QString ChannelInfo::label() const
{
    return name.isEmpty() ? id : id + QLatin1Char(' ') + name;
}

QString ChannelInfo::displayLabel() const
{
    const QString shown = displayName();
    return shown.isEmpty() ? id : id + QLatin1Char(' ') + shown;
}

QString ChannelInfo::deviceLabel() const
{
    const QString who = deviceName.isEmpty() ? device : deviceName;
    return who.isEmpty() ? displayLabel() : who + QStringLiteral(": ") + displayLabel();
}

int ChannelInfo::displayDecimals(double magnitude) const
{
    if (decimals >= 0)
        return decimals;
    if (!(magnitude > 0) || !std::isfinite(magnitude))
        return 3;
    return std::clamp(4 - int(std::floor(std::log10(magnitude))), 0, 9);
}

ChannelInfo ChannelInfo::forObject(ObjectAddress address, const ObjectDictionary &dictionary,
                                   const QString &device, int rateMs, const AddressFormat *format)
{
    ChannelInfo info;
    info.addressFormat = format ? format : &dictionary.addressFormat();
    info.id = info.addressFormat->format(address);
    info.address = address;
    info.device = device;
    info.sourceRateMs = rateMs;
    if (const ObjectDef *def = dictionary.find(address)) {
        info.name = def->name;
        info.localNames = def->localNames;
        info.unit = def->unit;
        info.scale = def->factor;
        info.offset = def->offset;
        // Integers shown with their scale keep the scale's decimals (0.01 -> 2); floating-point
        // values get theirs from the values shown.
        if (def->decimals >= 0)
            info.decimals = def->decimals;
        else if (datatype::isInteger(def->type))
            info.decimals = decimalsOf(def->factor);
    } else {
        info.decimals = 0; // read as an integer
    }
    return info;
}

} // namespace db::scope
