// A simulated CANopen node (SDO server, LSS slave, NMT, error control) fed hostile frames from
// the bus: each frame is an 11-bit id, a length and up to 8 data bytes.
#include "canopen/device/simulatednode.h"
#include "fuzzsupport.h"
#include "objectdefs.h"

#include <QCanBusFrame>

using namespace db;
using namespace db::canopen;

namespace {

using test::objectDef;

ObjectDictionary dictionary()
{
    ObjectDictionary dict;
    dict.insert(objectDef(0x1000, 0, DataType::Unsigned32, Access::ReadOnly, 0x00020192u));
    dict.insert(
        objectDef(0x1008, 0, DataType::VisibleString, Access::Const, QStringLiteral("node")));
    dict.insert(objectDef(0x1017, 0, DataType::Unsigned16, Access::ReadWrite, 0u));
    dict.insert(objectDef(0x1018, 0, DataType::Unsigned8, Access::Const, 4u));
    for (quint8 s = 1; s <= 4; ++s)
        dict.insert(objectDef(0x1018, s, DataType::Unsigned32, Access::Const, 0x100u + s));
    ObjectDef limited = objectDef(0x2000, 0, DataType::Unsigned16, Access::ReadWrite, 10u);
    limited.minimum = 10u;
    limited.maximum = 1000u;
    dict.insert(limited);
    dict.insert(objectDef(0x2001, 0, DataType::Integer32, Access::ReadWrite, 0));
    dict.insert(objectDef(0x2010, 0, DataType::Domain, Access::ReadWrite));
    dict.insert(objectDef(0x2011, 0, DataType::VisibleString, Access::ReadWrite));
    return dict;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::ensureApplication();
    static const ObjectDictionary dict = dictionary();
    fuzz::Input in(data, size);
    SimulatedNode node(dict, 5);
    node.start();
    while (!in.atEnd()) {
        const quint16 id = in.u16() & 0x7FF;
        const QByteArray payload = in.chunk(8);
        node.receive(QCanBusFrame(id, payload));
    }
    return 0;
}
