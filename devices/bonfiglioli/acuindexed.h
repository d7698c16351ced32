#pragma once

// Index parameters of the simulated ACU: parameters that hold 16 or 32 indices instead of four
// data sets (motion blocks, the PLC function table, the multiplexers). A write-index parameter
// selects where writes go (1..n EEPROM index, 0 all indices in EEPROM, n+1 all in RAM, n+2..2n+1
// RAM index), a read-index parameter which index reads return (1..n). Each index has an EEPROM
// and a RAM image; the index selections are volatile.

#include "acustore.h"
#include "vabus/vabuscodec.h"

#include <QHash>

namespace db::bonfiglioli {

class AcuIndexed
{
public:
    // True for the indexing parameters and the indexed ones.
    bool handles(quint16 parameter) const;
    // An access to one of them; store gives types and limits and counts EEPROM writes.
    AcuStore::Outcome access(const vabus::Telegram &request, AcuStore &store);
    // RAM images return to the EEPROM images; the selections to 0.
    void powerCycle();
    // The RAM image of one index (the value the drive works with); 0 when never written.
    qlonglong value(quint16 parameter, int index) const
    {
        return m_ram.value(key(parameter, index)).toLongLong();
    }
    // Both images, without checks (for the simulator's presets).
    void preset(quint16 parameter, int index, qlonglong raw)
    {
        m_ram.insert(key(parameter, index), QVariant::fromValue(raw));
        m_eeprom.insert(key(parameter, index), QVariant::fromValue(raw));
    }

private:
    struct Group
    {
        quint16 writeIndex;
        quint16 readIndex;
        int count; // 16 or 32
        QList<quint16> parameters;
    };
    static const QList<Group> &groups();
    static const Group *groupOf(quint16 parameter);
    static quint32 key(quint16 parameter, int index) { return (quint32(parameter) << 8) | index; }

    QHash<quint16, quint16> m_selection; // index parameter -> value
    QHash<quint32, QVariant> m_eeprom;
    QHash<quint32, QVariant> m_ram;
};

} // namespace db::bonfiglioli
