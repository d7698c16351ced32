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

// Votes per octet over all observations.
// Octet confidence = (votes for the winner / all votes) * min(1, votes for the winner / 2):
// a single reading gives 0.5, two agreeing readings 1.0, three against one 0.75.
// The IP confidence is the lowest octet confidence; kConfident (0.75) means at least two
// agreeing readings of every octet and a 3:1 majority, which is the manual's "two identical
// texts in a row" made per octet.
class IpVoter
{
public:
    static constexpr double kConfident = 0.75;

    void add(const IpObservation &observation);
    IpEstimate estimate() const;
    int observations() const { return m_count; }

private:
    std::array<std::map<int, int>, 4> m_votes;
    std::vector<std::array<int, 4>> m_complete;
    int m_count = 0;
};

} // namespace db::morse
