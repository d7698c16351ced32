// NM17x display PDOs and control words as a master receives or a display is sent them: every
// decoder on any payload; what decodes must encode to a payload that decodes the same.
#include "devices/nm17x/nm17xpdo.h"
#include "fuzzsupport.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::Input in(data, size);
    while (!in.atEnd()) {
        const quint8 which = in.byte();
        const QByteArray payload = in.chunk(8);
        switch (which % 5) {
        case 0:
            if (const auto b = nm17x::decodeBroadcast(payload)) {
                const auto again = nm17x::decodeBroadcast(nm17x::encodeBroadcast(*b));
                if (!again || !(*again == *b))
                    fuzz::finding("an NM17x broadcast does not survive encode -> decode");
            }
            break;
        case 1:
            if (const auto c = nm17x::decodePositionCommand(payload)) {
                const auto again = nm17x::decodePositionCommand(nm17x::encodePositionCommand(*c));
                if (!again || !(*again == *c))
                    fuzz::finding("an NM17x position command does not survive encode -> decode");
            }
            break;
        case 2:
            (void)nm17x::decodeTpdo1(payload);
            break;
        case 3:
            (void)nm17x::decodeTpdo2(payload);
            break;
        default:
            (void)nm17x::classify(quint16(quint8(payload.size() > 0 ? payload.at(0) : 0)
                                          | quint8(payload.size() > 1 ? payload.at(1) : 0) << 8));
            break;
        }
    }
    return 0;
}
