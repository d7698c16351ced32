// VABus/TCP answers from an inverter: the framer fed in pieces of any size, every telegram
// decoded, its data decoded as every carried type; the framer never holds more than one
// telegram's worth of bytes.
#include "core/datatype.h"
#include "fuzzsupport.h"
#include "vabus/vabuscodec.h"
#include "vabus/vabusframer.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::Input in(data, size);
    vabus::Framer framer;
    while (!in.atEnd()) {
        for (const Result<vabus::Frame> &f : framer.feed(in.chunk(40))) {
            if (!f)
                continue;
            (void)vabus::decode(f->bytes);
            if (f->kind != vabus::Frame::Kind::Telegram)
                continue;
            (void)vabus::encode(f->telegram);
            (void)vabus::errorText(f->telegram.errorCode());
            for (const DataType t : datatype::all())
                if (vabus::isCarried(t))
                    (void)vabus::decodeValue(t, f->telegram.data);
        }
        if (framer.bufferedBytes() > vabus::kMaxTelegramBytes)
            fuzz::finding("VABus framer holds more than one telegram");
    }
    return 0;
}
