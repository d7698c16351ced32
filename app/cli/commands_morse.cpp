#include "commands_morse.h"

#include "morse/decode/decoder.h"
#include "morse/input/morseinput.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

int morse(Context &c)
{
    const QString path = c.args.at(0);
    std::optional<QRect> region;
    if (c.args.size() > 1) {
        region = morseio::parseRegion(c.args.at(1));
        if (!region) {
            c.err << Tr::tr("drivebench-cli: region must be X,Y,W,H in frame pixels, got \"%1\"")
                         .arg(c.args.at(1))
                  << Qt::endl;
            return ExitUsage;
        }
    }
    const auto rec = morseio::readRecording(path, region);
    if (!rec) {
        c.err << "drivebench-cli: " << rec.error().message() << Qt::endl;
        return ExitFailure;
    }
    if (c.options.verbose) {
        c.out << "source: " << rec->source << ", " << rec->samples.size() << " samples";
        if (!rec->region.isEmpty())
            c.out << ", LED region " << rec->region.x() << ',' << rec->region.y() << ','
                  << rec->region.width() << ',' << rec->region.height();
        c.out << Qt::endl;
    }
    if (rec->frame.isNull() == false && rec->region.isEmpty()) {
        c.err << Tr::tr("drivebench-cli: %1: no LED found: no region of the video blinks (give "
                        "the region as X,Y,W,H)")
                     .arg(path)
              << Qt::endl;
        return ExitFailure;
    }
    morse::Decoder decoder;
    decoder.feed(rec->samples);
    decoder.finish();
    const morse::DecodeResult r = decoder.result();
    // A recording cut at gaps in time is said on success too (on failure the reason says it).
    if (!decoder.gapNote().isEmpty() && r.reason == morse::Reason::None)
        c.out << "note: " << decoder.gapNote() << Qt::endl;
    if (!r.text.isEmpty())
        c.out << "text: " << r.text << Qt::endl;
    if (r.unit > 0.0)
        c.out << "unit: " << QString::number(r.unit * 1000.0, 'f', 1) << " ms" << Qt::endl;
    if (r.ip.complete()) {
        c.out << "ip: " << r.ip.toString() << " (confidence "
              << QString::number(r.ip.confidence * 100.0, 'f', 0) << " %, " << r.ip.messages
              << (r.ip.messages == 1 ? " message" : " messages") << ")" << Qt::endl;
    }
    if (r.reason != morse::Reason::None) {
        c.err << "drivebench-cli: " << path << ": " << decoder.diagnosis().message() << Qt::endl;
        return ExitFailure;
    }
    return ExitOk;
}

} // namespace db::cli
