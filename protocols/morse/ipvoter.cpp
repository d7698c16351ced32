#include "ipvoter.h"

#include <QList>

#include <algorithm>
#include <limits>

namespace db::morse {
namespace {

// 1-3 decimal digits, 0..255; -1 otherwise.
int octetValue(QStringView field)
{
    if (field.isEmpty() || field.size() > 3)
        return -1;
    int v = 0;
    for (QChar c : field) {
        if (!c.isDigit())
            return -1;
        v = v * 10 + c.digitValue();
    }
    return v <= 255 ? v : -1;
}

IpObservation parseStretch(QStringView s, bool closed)
{
    IpObservation out;
    int count = 0;
    const auto ip = s.lastIndexOf(QLatin1String("IP"));
    if (ip >= 0) {
        const QList<QStringView> fields = s.mid(ip + 2).split(QLatin1Char('+'));
        // A closed message must have exactly four fields; otherwise a '+' was lost or added
        // and the positions of the octets are unknown.
        if (closed && fields.size() != 4)
            return {};
        for (int i = 0; i < 4 && i < fields.size(); ++i) {
            const bool terminated = i < fields.size() - 1 || closed;
            const int v = octetValue(fields[i]);
            if (!terminated || (v < 0 && !closed))
                break;
            out.octets[static_cast<std::size_t>(i)] = v;
            count += v >= 0 ? 1 : 0;
        }
        out.complete = count == 4;
        return out;
    }
    if (!closed)
        return {};
    // No "IP": the start was lost. Read backward from ':' while fields are opened by '+'.
    const QList<QStringView> fields = s.split(QLatin1Char('+'));
    for (int j = 0; j < 3 && j + 1 < fields.size(); ++j) {
        const int v = octetValue(fields[fields.size() - 1 - j]);
        if (v < 0)
            break;
        out.octets[static_cast<std::size_t>(3 - j)] = v;
        ++count;
    }
    return count >= 2 ? out : IpObservation {};
}

} // namespace

std::vector<IpObservation> parseIpObservations(const QString &text)
{
    std::vector<IpObservation> out;
    qsizetype begin = 0;
    for (qsizetype i = 0; i <= text.size(); ++i) {
        const bool end = i == text.size();
        if (!end && text[i] != QLatin1Char(':') && text[i] != QLatin1Char(' '))
            continue;
        const bool closed = !end && text[i] == QLatin1Char(':');
        IpObservation obs = parseStretch(QStringView(text).mid(begin, i - begin), closed);
        obs.endIndex = static_cast<int>(std::min(i + 1, text.size()));
        if (std::any_of(obs.octets.begin(), obs.octets.end(), [](int v) { return v >= 0; }))
            out.push_back(obs);
        begin = i + 1;
    }
    return out;
}

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
    m_readings.push_back(std::move(r));
    if (obs.complete)
        m_complete.push_back(obs.octets);
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
    e.messages = static_cast<int>(std::count(m_complete.begin(), m_complete.end(), e.octets));
    return e;
}

} // namespace db::morse
