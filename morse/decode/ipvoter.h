#pragma once

#include "morsetypes.h"

#include <QString>

#include <array>
#include <map>
#include <vector>

namespace db::morse {

// What one message read by the sequence decoder (messageparser.h) says about the IP address
// (movingcap.md section 2.2: "MC+IP192+168+2+150:", '+' instead of '.', ':' ends the message).
struct IpObservation
{
    std::array<int, 4> octets { -1, -1, -1, -1 }; // -1: not read in this message
    bool complete = false; // all four from one "IP...:" message
    // Vote weight of each octet, (0, IpVoter::kMaxWeight]: 1 for a plain reading, less when an
    // element of it was close to the dit/dah boundary (see messageparser.h).
    std::array<double, 4> weight { 1.0, 1.0, 1.0, 1.0 };
    // Soft evidence from the sequence decoder (messageparser.h), per octet read: for each value
    // the parse could also have given that octet, how much worse (nats) the best such parse
    // explains the measured lengths than the best parse overall (0 for the value read). Empty:
    // the reading says only "this value, with this weight". An octet still
    // arriving when the stretch ends (octets[k] == -1) may have costs too: its digits so far
    // fit several values ("20": 20 and 200-209 cost nothing, the others more).
    std::array<std::map<int, double>, 4> cost;
};

// Combines the readings into the most likely address. Every reading gives every value v of
// an octet it read a cost in nats: its soft cost for v (IpObservation::cost) capped at
// kMaxWeight * kNatsPerWeight, or, for a reading without soft costs, 0 for the value read and
// weight * kNatsPerWeight for any other. That is a log-likelihood ratio when the readings are
// independent: two readings that agree but are each unsure against a different rival (another
// digit, another split into characters) confirm each other; two unsure against the same rival
// do not. A reading costs an address the sum over its octets, capped at kMessageCap: noise that
// garbles one message garbles several of its octets, and such a reading must not outvote the
// clean ones octet by octet. The voted address has the least total cost over all readings
// (searched over the few cheapest values of each octet). An octet's lead is how much more the
// best address with another value there costs; its confidence is lead / (kLead *
// kNatsPerWeight), clamped to [0, 1], once two readings read its value, and min(kSingle, lead /
// (2 * kNatsPerWeight)) while only one did (the others garbled or cut off). A reading whose soft
// cost for a value is within kTie of its own reading reads both: it cannot tell them apart, and
// which of the two its best parse names is chance. With plain readings (weight 1, no soft
// costs): one reading 0.5, two agreeing 1.0, 2:1 0.67, 3:1 1.0. The IP confidence is the lowest
// octet confidence; kConfident (0.75) is the manual's "two identical texts in a row" made per
// octet and weighted.
class IpVoter
{
public:
    static constexpr double kConfident = 0.75;
    static constexpr double kLead = 1.5;
    static constexpr double kSingle = 0.5;
    static constexpr double kTie = 0.5;
    static constexpr double kMaxWeight = 1.5;
    static constexpr double kNatsPerWeight = 4.0;
    static constexpr double kMessageCap = 2.0 * kMaxWeight * kNatsPerWeight;
    static constexpr std::size_t kCandidates = 5; // values per octet searched jointly

    void add(const IpObservation &observation);
    IpEstimate estimate() const;
    int observations() const { return m_count; }

private:
    struct Reading
    {
        std::array<std::map<int, double>, 4> cost; // by value; values not listed cost `cap`
        std::array<double, 4> cap {}; // 0: octet not read
        std::array<int, 4> value { -1, -1, -1, -1 }; // the value read
        // Nats this reading charges `v` for octet i: 0 where it did not read octet i.
        double costOf(std::size_t i, int v) const
        {
            if (cap[i] <= 0.0)
                return 0.0;
            const auto it = cost[i].find(v);
            return it == cost[i].end() ? cap[i] : it->second;
        }
        // Whether this reading read octet i whole as `v`, or as a value it cannot tell from v
        // (within kTie nats: "2" and "8" each with two dits merged by noise are the same marks).
        bool reads(std::size_t i, int v) const
        {
            if (value[i] < 0)
                return false;
            const auto it = cost[i].find(v);
            return it != cost[i].end() && it->second <= kTie;
        }
    };
    std::vector<Reading> m_readings;
    std::vector<std::size_t> m_complete; // the readings of complete messages
    int m_count = 0;
};

} // namespace db::morse
