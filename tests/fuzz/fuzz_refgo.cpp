// RefGo answers from a drive: the framer fed in pieces of any size, then every line of every
// answer through the codec's parsers (object reads, status words, numbers, requests).
#include "fuzzsupport.h"
#include "refgo/refgocodec.h"
#include "refgo/refgoframer.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::Input in(data, size);
    refgo::Framer framer;
    while (!in.atEnd()) {
        const QByteArray piece = in.chunk(64);
        for (const Result<refgo::Answer> &a : framer.feed(piece)) {
            if (!a)
                continue;
            (void)refgo::parseRequest(a->echo);
            for (const QString &line : a->lines) {
                (void)refgo::parseObjectRead(line);
                (void)refgo::parseTpsr(line);
                (void)refgo::parseTs(line);
                (void)refgo::parseNumber(line);
            }
        }
        if (framer.bufferedBytes() > refgo::Framer::kMaxAnswerBytes)
            fuzz::finding("RefGo framer holds more than kMaxAnswerBytes");
    }
    return 0;
}
