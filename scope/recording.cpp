#include "recording.h"

#include "core/objectaddress.h"

#include <algorithm>

namespace db::scope {

bool Recording::isEmpty() const
{
    return std::all_of(channels.cbegin(), channels.cend(),
                       [](const RecordedChannel &c) { return c.buffer.isEmpty(); });
}

double Recording::startTime() const
{
    double t = std::numeric_limits<double>::infinity();
    for (const RecordedChannel &c : channels) {
        if (!c.buffer.isEmpty())
            t = std::min(t, c.buffer.firstTime());
    }
    return std::isinf(t) ? 0 : t;
}

double Recording::endTime() const
{
    double t = -std::numeric_limits<double>::infinity();
    for (const RecordedChannel &c : channels) {
        if (!c.buffer.isEmpty())
            t = std::max(t, c.buffer.lastTime());
    }
    return std::isinf(t) ? 0 : t;
}

int Recording::indexOf(const QString &id) const
{
    for (int i = 0; i < channels.size(); ++i) {
        if (channels[i].info.id == id)
            return i;
    }
    // Another spelling of the address ("6064:00", "0x6064:0"), as each channel's device
    // writes addresses.
    for (int i = 0; i < channels.size(); ++i) {
        const ChannelInfo &info = channels[i].info;
        const auto wanted = info.addressFormat->parse(id);
        if (wanted && info.address == *wanted)
            return i;
    }
    return -1;
}

Recording Recording::slice(double t0, double t1) const
{
    if (t0 > t1)
        std::swap(t0, t1);
    Recording out = *this;
    for (int c = 0; c < channels.size(); ++c) {
        const TraceBuffer &src = channels[c].buffer;
        const qint64 first = src.lowerBound(t0);
        const qint64 last = src.upperBound(t1);
        TraceBuffer buffer(std::max<qint64>(1, last - first));
        for (qint64 i = first; i < last; ++i) {
            if (src.startsGap(i))
                buffer.markGap();
            buffer.append(src.time(i), src.value(i));
        }
        buffer.setCounters(src.droppedOverwritten(), src.lostAtSource());
        out.channels[c].buffer = std::move(buffer);
    }
    return out;
}

} // namespace db::scope
