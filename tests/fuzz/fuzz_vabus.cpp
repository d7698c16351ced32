// VABus/TCP answers from an inverter: the framer fed in pieces of any size, every telegram
// decoded, its data decoded as every carried type and as a block answer (parameter 19) of a few
// block layouts; the framer never holds more than one telegram's worth of bytes.
#include "core/datatype.h"
#include "fuzzsupport.h"
#include "vabus/vabusblock.h"
#include "vabus/vabuscodec.h"
#include "vabus/vabusframer.h"

using namespace db;

namespace {
// Word and double-word layouts of a block answer.
const QList<QList<vabus::BlockItem>> &blockLayouts()
{
    static const QList<QList<vabus::BlockItem>> layouts = {
        { { { 411, 0 }, DataType::Unsigned16 } },
        { { { 210, 0 }, DataType::Integer32 },
          { { 211, 0 }, DataType::Integer16 },
          { { 213, 0 }, DataType::Integer16 } },
        { { { 240, 0 }, DataType::Integer32 }, { { 228, 0 }, DataType::Integer32 } },
    };
    return layouts;
}
} // namespace

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
            for (const auto &layout : blockLayouts()) {
                const auto values = vabus::decodeBlock(f->telegram.data, layout);
                if (values && values->size() != layout.size())
                    fuzz::finding("VABus block answer decoded to the wrong number of values");
            }
        }
        if (framer.bufferedBytes() > vabus::kMaxTelegramBytes)
            fuzz::finding("VABus framer holds more than one telegram");
    }
    return 0;
}
