#pragma once

#include "morsetypes.h"

#include <QString>

#include <array>
#include <map>
#include <vector>

namespace db::morse {

// What one stretch of decoded text says about the IP address (movingcap.md section 2.2:
// "MC+IP192+168+2+150:", '+' instead of '.', ':' ends the message).
struct IpObservation
{
    std::array<int, 4> octets { -1, -1, -1, -1 }; // -1: not in this stretch
    bool complete = false; // all four from one "IP...:" message
    int endIndex = 0; // index in the text just past the stretch
    // Vote weight of each octet, (0, IpVoter::kMaxWeight]: 1 for a plain reading, less when an
    // element of it was close to the dit/dah boundary (see messageparser.h).
    std::array<double, 4> weight { 1.0, 1.0, 1.0, 1.0 };
    // From the sequence decoder: the weight of each digit of each octet (weight is their
    // least); digits[k] == 0 when not known.
    std::array<std::array<double, 3>, 4> digitWeight {};
    std::array<int, 4> digits {};
};

// Parses decoded text into observations. The text is split into stretches at ':' (end of a
// message) and ' ' (word gap: never inside a message). In each stretch:
//  - with "IP": the fields after the last "IP", split at '+'. A stretch closed by ':' must have
//    exactly four fields (a lost or extra '+' shifts every octet: dropped); each field that is
//    1-3 digits and 0..255 is an octet, an unreadable one ('?') is skipped. An open stretch
//    (message still arriving) gives the octets already closed by '+';
//  - without "IP" but closed by ':': the start was lost (recording began inside the message,
//    or "IP" was unreadable). Octets are read backward from ':' while each field is valid and
//    opened by '+'. At least two are needed, so that status text such as "ERR+5:" does not
//    vote.
// Other text is ignored.
std::vector<IpObservation> parseIpObservations(const QString &text);

// Weighted votes per octet over all observations. An octet's confidence is
//     lead / kLead, clamped to [0, 1], once it was read at least twice (lead = summed weight of
//     the winning value minus that of all others); min(kSingle, weight / 2) after one reading.
// With plain readings (weight 1): one reading 0.5, two agreeing 1.0, 2:1 0.67, 3:1 1.0. A clear
// reading (weight up to kMaxWeight) outvotes one with an element at the dit/dah boundary
// (small weight), so that two readings can already be confident when they disagree only
// where one of them was unsure. Readings that agree and carry digit weights support their value
// digit by digit: the least over the digits of the summed digit weights (two readings each
// unsure at a different digit confirm each other's unsure digit). The IP confidence is the
// lowest octet confidence; kConfident
// (0.75) is the manual's "two identical texts in a row" made per octet and weighted.
class IpVoter
{
public:
    static constexpr double kConfident = 0.75;
    static constexpr double kLead = 1.5;
    static constexpr double kSingle = 0.5;
    static constexpr double kMaxWeight = 1.5;

    void add(const IpObservation &observation);
    IpEstimate estimate() const;
    int observations() const { return m_count; }

private:
    struct Votes
    {
        double weight = 0.0; // summed
        std::array<double, 3> digits {}; // summed digit weights
        int digitCount = 0; // digits of the readings, 0 before the first
        bool perDigit = true; // every reading carried digit weights for as many digits
    };
    std::array<std::map<int, Votes>, 4> m_votes; // by octet value
    std::vector<std::array<int, 4>> m_complete;
    std::array<int, 4> m_readings {};
    int m_count = 0;
};

} // namespace db::morse
