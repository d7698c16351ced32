// The CAN monitor's decoder on any sequence of frames (standard and extended ids, remote
// frames, any length), with a dictionary for node 1 so that values are formatted too.
#include "canopen/framedecoder.h"
#include "fuzzsupport.h"

#include <QCanBusFrame>

using namespace db;
using namespace db::canopen;

namespace {

ObjectDictionary dictionary()
{
    ObjectDictionary dict;
    const struct
    {
        quint16 index;
        DataType type;
    } objects[] = { { 0x1000, DataType::Unsigned32 }, { 0x1008, DataType::VisibleString },
                    { 0x6041, DataType::Unsigned16 }, { 0x6064, DataType::Integer32 },
                    { 0x6060, DataType::Integer8 },   { 0x2000, DataType::Real32 },
                    { 0x2001, DataType::Unsigned64 }, { 0x2002, DataType::Domain } };
    for (const auto &o : objects) {
        ObjectDef d;
        d.address = { o.index, 0 };
        d.name = QStringLiteral("object %1").arg(o.index, 4, 16);
        d.type = o.type;
        dict.insert(d);
    }
    return dict;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const ObjectDictionary dict = dictionary();
    fuzz::Input in(data, size);
    FrameDecoder decoder;
    decoder.setDictionary(1, dict);
    while (!in.atEnd()) {
        const quint8 flags = in.byte();
        const quint32 id =
            (flags & 1) ? ((quint32(in.u16()) << 16 | in.u16()) & 0x1FFFFFFF) : (in.u16() & 0x7FF);
        QCanBusFrame frame(id, in.chunk(8));
        frame.setExtendedFrameFormat(flags & 1);
        if (flags & 2)
            frame.setFrameType(QCanBusFrame::RemoteRequestFrame);
        const DecodedFrame d = decoder.decode(frame);
        (void)d.text.size();
    }
    return 0;
}
