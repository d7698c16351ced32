#include "pollschedule.h"

#include <algorithm>

namespace db::scope {

int PollSchedule::addChannel(qint64 periodNs)
{
    m_channels.append({ std::max<qint64>(0, periodNs), 0, false });
    return int(m_channels.size()) - 1;
}

void PollSchedule::start(qint64 nowNs)
{
    for (Channel &c : m_channels) {
        c.nextSlotNs = nowNs;
        c.inFlight = false;
    }
}

QList<PollSchedule::Read> PollSchedule::due(qint64 nowNs)
{
    QList<int> fixed;
    QList<int> free;
    for (int i = 0; i < m_channels.size(); ++i) {
        const Channel &c = m_channels.at(i);
        if (c.inFlight)
            continue;
        if (c.periodNs == 0)
            free.append(i);
        else if (c.nextSlotNs <= nowNs)
            fixed.append(i);
    }
    // The slot each due channel serves now: the oldest within its catch-up window.
    const auto served = [this, nowNs](int i) {
        const Channel &c = m_channels.at(i);
        const qint64 owed = (nowNs - c.nextSlotNs) / c.periodNs + 1;
        return c.nextSlotNs + std::max<qint64>(0, owed - maxOwed(c.periodNs)) * c.periodNs;
    };
    std::stable_sort(fixed.begin(), fixed.end(),
                     [&served](int a, int b) { return served(a) < served(b); });
    QList<Read> reads;
    reads.reserve(fixed.size() + free.size());
    for (int i : fixed) {
        Channel &c = m_channels[i];
        // Slots begun and not read; those beyond the window can no longer be caught up.
        const qint64 owed = (nowNs - c.nextSlotNs) / c.periodNs + 1;
        const qint64 skipped = std::max<qint64>(0, owed - maxOwed(c.periodNs));
        c.nextSlotNs += (skipped + 1) * c.periodNs;
        c.inFlight = true;
        reads.append({ i, skipped });
    }
    for (int i : free) {
        m_channels[i].inFlight = true;
        reads.append({ i, 0 });
    }
    return reads;
}

qint64 PollSchedule::maxOwed(qint64 periodNs) const
{
    // The slot being served counts too: with no window, only the newest slot may be owed.
    if (m_catchUpNs == 0)
        return 1;
    return std::max(kMinCatchUpSlots, m_catchUpNs / periodNs);
}

void PollSchedule::finished(int channel)
{
    if (channel >= 0 && channel < m_channels.size())
        m_channels[channel].inFlight = false;
}

std::optional<qint64> PollSchedule::nextDueNs() const
{
    std::optional<qint64> next;
    for (const Channel &c : m_channels) {
        if (c.inFlight)
            continue;
        // A free-running channel without a read in flight is due at once (its slot stays at
        // the start, which has passed).
        const qint64 at = c.nextSlotNs;
        if (!next || at < *next)
            next = at;
    }
    return next;
}

QList<qint64> PollSchedule::lostUntil(qint64 nowNs)
{
    QList<qint64> lost(m_channels.size(), 0);
    for (int i = 0; i < m_channels.size(); ++i) {
        Channel &c = m_channels[i];
        if (c.periodNs == 0 || c.nextSlotNs > nowNs)
            continue;
        // Slot k is over when slot k + 1 has begun.
        const qint64 ended = (nowNs - c.nextSlotNs) / c.periodNs;
        c.nextSlotNs += ended * c.periodNs;
        lost[i] = ended;
    }
    return lost;
}

} // namespace db::scope
