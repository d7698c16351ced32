#pragma once
// How `drivebench-cli record` ends: what is written, what is printed, which exit code.
#include "commands.h"

namespace db::scope {
class PollingSource;
class Recorder;
} // namespace db::scope

namespace db::cli {

struct RecordOutcome
{
    const scope::Recorder &recorder; // stopped
    const scope::PollingSource *polling = nullptr; // null for PDO sampling
    double elapsedS = 0; // from start to stop
    Error failure; // a source error that stopped the recording
    int signal = 0; // SIGINT / SIGTERM that stopped it; 0 when none
    bool triggerTimedOut = false;
    QString trigger;
    double waitS = 0;
};

// Writes the recording to c.output and reports it; returns the exit code.
// - No sample at all: nothing is written; one line names why (the reads' own error, a read that
//   never got an answer, the source error or the signal) with that cause's exit code.
// - Samples: the file is written (atomically) and summarised on stdout; then the first of: the
//   signal (128 + its number), the source error, failed reads (the last one's exit code), samples
//   lost because the link or the PDOs were too slow (1).
int finishRecording(Context &c, const RecordOutcome &o);

} // namespace db::cli
