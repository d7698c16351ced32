#include "channel.h"

#include "core/objectdictionary.h"

namespace db::scope {

QString ChannelInfo::label() const
{
    return name.isEmpty() ? id : id + QLatin1Char(' ') + name;
}

QString ChannelInfo::displayLabel() const
{
    const QString shown = displayName();
    return shown.isEmpty() ? id : id + QLatin1Char(' ') + shown;
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
    }
    return info;
}

} // namespace db::scope
