#include "ipvoter.h"

#include <QList>

#include <algorithm>

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
    for (std::size_t i = 0; i < 4; ++i) {
        if (obs.octets[i] >= 0) {
            Votes &v = m_votes[i][obs.octets[i]];
            v.weight += obs.weight[i];
            v.perDigit = v.perDigit && obs.digits[i] > 0
                && (v.digitCount == 0 || v.digitCount == obs.digits[i]);
            v.digitCount = obs.digits[i];
            for (std::size_t d = 0; d < 3; ++d)
                v.digits[d] += obs.digitWeight[i][d];
            ++m_readings[i];
        }
    }
    if (obs.complete)
        m_complete.push_back(obs.octets);
    ++m_count;
}

IpEstimate IpVoter::estimate() const
{
    IpEstimate e;
    double confidence = 1.0;
    for (std::size_t i = 0; i < 4; ++i) {
        double total = 0;
        double best = 0;
        double support = 0;
        for (const auto &[value, votes] : m_votes[i]) {
            total += votes.weight;
            if (votes.weight > best) {
                best = votes.weight;
                e.octets[i] = value;
                support = best;
                if (votes.perDigit) {
                    const auto n = static_cast<std::ptrdiff_t>(votes.digitCount);
                    const double least =
                        *std::min_element(votes.digits.begin(), votes.digits.begin() + n);
                    support = std::max(best, least);
                }
            }
        }
        const double lead = support - (total - best);
        const double c =
            m_readings[i] >= 2 ? std::clamp(lead / kLead, 0.0, 1.0) : std::min(kSingle, best / 2.0);
        confidence = std::min(confidence, c);
    }
    e.confidence = confidence;
    e.messages = static_cast<int>(std::count(m_complete.begin(), m_complete.end(), e.octets));
    return e;
}

} // namespace db::morse
