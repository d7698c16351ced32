#include "acuindexed.h"

#include "core/valuecodec.h"

namespace db::bonfiglioli {

using namespace db::vabus;

const QList<AcuIndexed::Group> &AcuIndexed::groups()
{
    static const QList<Group> all = [] {
        QList<quint16> positioning;
        for (quint16 p = 1202; p <= 1219; ++p)
            positioning.append(p);
        positioning += { 1247, 1248, 1260, 1261, 1262, 1263, 1264, 1265 };
        QList<quint16> functionTable;
        for (quint16 p = 1343; p <= 1352; ++p)
            functionTable.append(p);
        return QList<Group> {
            { 1200, 1201, 32, positioning },
            { 1341, 1342, 32, functionTable },
            { 1250, 1251, 16, { 1252 } },
            { 1420, 1421, 16, { 1422 } },
        };
    }();
    return all;
}

const AcuIndexed::Group *AcuIndexed::groupOf(quint16 parameter)
{
    for (const Group &g : groups()) {
        if (g.writeIndex == parameter || g.readIndex == parameter
            || g.parameters.contains(parameter))
            return &g;
    }
    return nullptr;
}

bool AcuIndexed::handles(quint16 parameter) const
{
    return groupOf(parameter) != nullptr;
}

AcuStore::Outcome AcuIndexed::access(const Telegram &request, AcuStore &store)
{
    const Group *g = groupOf(request.parameter);
    if (!g)
        return { UnknownParameter, {} };
    if (request.dataSet != 0 && request.dataSet != kRamDataSetOffset)
        return { InvalidDataSet, {} };
    const DataType type = store.type(request.parameter);
    const quint16 p = request.parameter;
    if (p == g->writeIndex || p == g->readIndex) {
        if (!request.write)
            return {
                NoError,
                encodeValue(type, QVariant::fromValue<qlonglong>(m_selection.value(p))).valueOr({})
            };
        if (request.data.size() != datatype::byteSize(type))
            return { LengthMismatch, {} };
        const qlonglong v = decodeValue(type, request.data).valueOr(-1).toLongLong();
        const int max = p == g->writeIndex ? 2 * g->count + 1 : g->count;
        if (v < 0 || v > max)
            return { InvalidValue, {} };
        m_selection.insert(p, quint16(v));
        return { NoError, request.data };
    }
    if (!request.write) {
        const int index = m_selection.value(g->readIndex);
        if (index < 1)
            return { InvalidValue, {} };
        const QVariant raw = m_ram.value(key(p, index), codec::normalize(type, 0).valueOr({}));
        return { NoError, encodeValue(type, raw).valueOr({}) };
    }
    if (type != DataType::VisibleString && request.data.size() != datatype::byteSize(type))
        return { LengthMismatch, {} };
    const auto raw = decodeValue(type, request.data);
    if (!raw)
        return { InvalidValue, {} };
    const int selection = m_selection.value(g->writeIndex);
    const bool ram = selection > g->count;
    const int first = ram ? selection - g->count - 1 : selection;
    QList<int> indices;
    if (first == 0) {
        for (int i = 1; i <= g->count; ++i)
            indices.append(i);
    } else {
        indices.append(first);
    }
    for (const int i : indices) {
        m_ram.insert(key(p, i), raw.value());
        if (!ram)
            m_eeprom.insert(key(p, i), raw.value());
    }
    if (!ram)
        store.countEepromWrite();
    return { NoError, request.data };
}

void AcuIndexed::powerCycle()
{
    m_ram = m_eeprom;
    m_selection.clear();
}

} // namespace db::bonfiglioli
