#pragma once

#include "morse/decode/decoder.h"
#include "signalgenerator.h"

#include <QString>

#include <array>
#include <vector>

namespace db::morse {

// Synthetic test corpus shared by tests/morse and bench/morse: random IPs, speeds, frame
// rates, exposures and start positions under one named condition. Deterministic per seed.
struct CorpusCondition
{
    QString name;
    double jitter = 0.0;
    double snrDb = std::numeric_limits<double>::infinity();
    double drift = 0.0; // ambient change per second, multiples of the amplitude (sign random)
    double gainDrift = 0.0; // auto-exposure swing
    double dutyError = 0.0; // units; sign random per case
    // Decodability limit: the dit must span at least this many sample periods. Below about
    // two frames per dit a camera cannot separate dits from the gaps between them.
    double minSamplesPerUnit = 2.0;
    std::vector<double> rates { 15.0, 25.0, 30.0, 60.0, 1000.0 }; // used in turn
    // Pause between two messages, units (the manual gives none). 0: 7-14 units, drawn per case;
    // 3: back to back (only a letter gap after ':').
    double repeatGap = 0.0;
    // runCase() streams in chunks of this length. Back to back, the second message's ':' is
    // complete (its letter gap past 2 units) 1 unit before the third message begins: chunks
    // longer than that would report the time of confidence too late.
    double chunkSeconds = 0.25;
};

struct CorpusCase
{
    SignalOptions signal;
    std::array<int, 4> ip {};
};

std::vector<CorpusCase> makeCorpus(const CorpusCondition &condition, int count, unsigned seed);

struct CaseOutcome
{
    bool exact = false; // final voted IP == truth
    bool confident = false; // final confidence >= threshold
    bool wrongConfident = false; // confident in a wrong IP at any time
    // Time from the start of the first complete message to the first confident IP, in
    // message periods as sent (k + the fraction of the k-th period after the first complete
    // message, with the jittered lengths of the messages): <= 2 is "before the third message
    // began"; < 0 when never confident.
    double repetitionsToConfident = -1.0;
    // The same in nominal periods (unjittered message length): jitter that stretches the first
    // two messages pushes their end past 2.0 here.
    double nominalRepetitionsToConfident = -1.0;
    Reason reason = Reason::None;
    QString decoded;
    QString text; // decoded text, for reports
};

// Streams the case through a Decoder in chunks of `chunkSeconds` and checks the result.
CaseOutcome runCase(const CorpusCase &c, double chunkSeconds = 0.25, DecoderOptions options = {});

QString ipText(const std::array<int, 4> &ip, QChar separator);

} // namespace db::morse
