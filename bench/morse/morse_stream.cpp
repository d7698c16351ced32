// Streaming cost of the LED Morse decoder on a long recording (not run by ctest).
//
//   morse_stream [pause-units=3] [repetitions=12] [snr-dB=6] [jitter=0.3]
//
// Generates the spec's message ("MC+IP192+168+2+150:") at 30 fps with a 120 ms dit, the given
// pause between messages (3: back to back, the whole recording one stretch), and feeds it to
// one Decoder frame by frame, as the live camera does. Prints the total decoding time, the
// slowest frame and the result.
#include "morse/decode/decoder.h"
#include "morse/synth/signalgenerator.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QStringList>
#include <QTextStream>

#include <algorithm>

using namespace db::morse;

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    auto arg = [&](int i, double fallback) {
        return args.size() > i ? args[i].toDouble() : fallback;
    };
    SignalOptions o;
    o.sampleRate = 30.0;
    o.unit = 0.12;
    o.repeatGap = arg(1, 3.0);
    o.repetitions = int(arg(2, 12.0));
    o.snrDb = arg(3, 6.0);
    o.jitter = arg(4, 0.3);
    o.startOffset = 0.3;
    o.seed = 3;
    const Signal sig = generateSignal(o);

    Decoder decoder;
    QElapsedTimer total;
    total.start();
    qint64 slowest = 0;
    for (const Sample &s : sig.samples) {
        QElapsedTimer frame;
        frame.start();
        decoder.feed(s);
        slowest = std::max(slowest, frame.nsecsElapsed());
    }
    decoder.finish();
    const double seconds = double(total.nsecsElapsed()) / 1e9;
    QTextStream(stdout) << sig.samples.size() << " frames ("
                        << QString::number(double(sig.samples.size()) / o.sampleRate, 'f', 0)
                        << " s of video), pause " << o.repeatGap << " units: decoded in "
                        << QString::number(seconds, 'f', 2) << " s, slowest frame "
                        << QString::number(double(slowest) / 1e6, 'f', 1) << " ms; ip "
                        << decoder.ip().toString() << " ("
                        << QString::number(decoder.ip().confidence * 100.0, 'f', 0) << " %)\n";
    return 0;
}
