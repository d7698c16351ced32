#include "ipvoter.h"

#include <algorithm>
#include <limits>

namespace db::morse {

void IpVoter::add(const IpObservation &obs)
{
    constexpr double softCap = kMaxWeight * kNatsPerWeight;
    Reading r;
    for (std::size_t i = 0; i < 4; ++i) {
        if (obs.octets[i] < 0 && obs.cost[i].empty())
            continue;
        if (obs.cost[i].empty()) {
            r.cap[i] = std::clamp(obs.weight[i], 0.01, kMaxWeight) * kNatsPerWeight;
        } else {
            r.cap[i] = softCap;
            for (const auto &[value, nats] : obs.cost[i]) {
                if (nats < softCap)
                    r.cost[i][value] = std::max(0.0, nats);
            }
        }
        if (obs.octets[i] < 0)
            continue; // a prefix of the octet (an open stretch): its costs, no value read
        r.cost[i][obs.octets[i]] = 0.0;
        r.value[i] = obs.octets[i];
    }
    if (obs.complete)
        m_complete.push_back(m_readings.size());
    m_readings.push_back(std::move(r));
    ++m_count;
}

IpEstimate IpVoter::estimate() const
{
    // Candidates per octet: the values read, the kCandidates other values with the least summed
    // cost (octets taken one by one), and kOther standing for every value no reading considers.
    constexpr int kOther = -2;
    std::array<std::vector<int>, 4> candidates;
    for (std::size_t i = 0; i < 4; ++i) {
        std::map<int, double> total;
        for (const Reading &r : m_readings) {
            if (r.cap[i] > 0.0) {
                for (const auto &entry : r.cost[i])
                    total.try_emplace(entry.first, 0.0);
            }
        }
        std::vector<std::pair<double, int>> ranked;
        for (auto &[value, sum] : total) {
            for (const Reading &r : m_readings)
                sum += r.costOf(i, value);
            ranked.emplace_back(sum, value);
        }
        std::sort(ranked.begin(), ranked.end());
        auto add = [&list = candidates[i]](int value) {
            if (std::find(list.begin(), list.end(), value) == list.end())
                list.push_back(value);
        };
        // Every value a reading read whole, then the cheapest others.
        for (const Reading &r : m_readings) {
            if (r.value[i] >= 0)
                add(r.value[i]);
        }
        const std::size_t read = candidates[i].size();
        for (std::size_t k = 0; k < ranked.size() && candidates[i].size() < read + kCandidates; ++k)
            add(ranked[k].second);
        candidates[i].push_back(kOther);
    }
    // cost[r][i][c]: reading r's cost for candidate c of octet i (0 where r did not read i).
    std::vector<std::array<std::vector<double>, 4>> cost(m_readings.size());
    for (std::size_t r = 0; r < m_readings.size(); ++r) {
        for (std::size_t i = 0; i < 4; ++i) {
            for (int value : candidates[i])
                cost[r][i].push_back(m_readings[r].costOf(i, value));
        }
    }
    // Every combination of candidates; per octet and candidate the cheapest address using it.
    std::array<std::vector<double>, 4> cheapest;
    for (std::size_t i = 0; i < 4; ++i)
        cheapest[i].assign(candidates[i].size(), std::numeric_limits<double>::infinity());
    std::array<std::size_t, 4> c {};
    while (true) {
        double total = 0.0;
        for (const auto &rc : cost)
            total += std::min(kMessageCap, rc[0][c[0]] + rc[1][c[1]] + rc[2][c[2]] + rc[3][c[3]]);
        for (std::size_t i = 0; i < 4; ++i)
            cheapest[i][c[i]] = std::min(cheapest[i][c[i]], total);
        std::size_t i = 0;
        while (i < 4 && ++c[i] == candidates[i].size())
            c[i++] = 0;
        if (i == 4)
            break;
    }
    IpEstimate e;
    double confidence = 1.0;
    for (std::size_t i = 0; i < 4; ++i) {
        // The voted value is one that some reading read whole (a prefix alone names none).
        auto support = [&](int value) {
            return std::count_if(m_readings.begin(), m_readings.end(),
                                 [&](const Reading &r) { return r.reads(i, value); });
        };
        std::size_t at = candidates[i].size();
        for (std::size_t k = 0; k < candidates[i].size(); ++k) {
            if (candidates[i][k] >= 0 && support(candidates[i][k]) > 0
                && (at == candidates[i].size() || cheapest[i][k] < cheapest[i][at]))
                at = k;
        }
        if (at == candidates[i].size()) {
            confidence = 0.0;
            continue;
        }
        double second = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < cheapest[i].size(); ++k) {
            if (k != at)
                second = std::min(second, cheapest[i][k]);
        }
        e.octets[i] = candidates[i][at];
        const double lead = std::max(0.0, second - cheapest[i][at]);
        const double conf = support(e.octets[i]) >= 2
            ? std::clamp(lead / (kLead * kNatsPerWeight), 0.0, 1.0)
            : std::min(kSingle, lead / (2.0 * kNatsPerWeight));
        confidence = std::min(confidence, conf);
    }
    e.confidence = confidence;
    e.messages =
        static_cast<int>(std::count_if(m_complete.begin(), m_complete.end(), [&](std::size_t r) {
            for (std::size_t i = 0; i < 4; ++i) {
                if (!m_readings[r].reads(i, e.octets[i]))
                    return false;
            }
            return true;
        }));
    return e;
}

} // namespace db::morse
