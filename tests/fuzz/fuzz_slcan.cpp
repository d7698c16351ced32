// SLCAN text from an adapter or a tunnelling drive: the decoder fed in pieces; every frame it
// accepts must survive encodeFrame() -> parseLine() unchanged.
#include "fuzzsupport.h"
#include "transport/slcancodec.h"

#include <QCanBusFrame>

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::Input in(data, size);
    slcan::Decoder decoder;
    while (!in.atEnd()) {
        for (const slcan::Message &m : decoder.feed(in.chunk(40))) {
            if (m.kind != slcan::Message::Kind::Frame)
                continue;
            const slcan::Message again = slcan::parseLine(slcan::encodeFrame(m.frame).trimmed());
            if (again.kind != slcan::Message::Kind::Frame
                || again.frame.frameId() != m.frame.frameId()
                || again.frame.payload() != m.frame.payload()
                || again.frame.hasExtendedFrameFormat() != m.frame.hasExtendedFrameFormat()
                || again.frame.frameType() != m.frame.frameType())
                fuzz::finding("an SLCAN frame does not survive encode -> parse");
        }
        if (decoder.pendingBytes() > slcan::kMaxLineLength)
            fuzz::finding("SLCAN decoder holds more than kMaxLineLength bytes");
    }
    return 0;
}
