#pragma once

// The parameter memory of one simulated ACU: every described parameter with an EEPROM image
// and a RAM image per data set, checked the way the inverter checks VABus accesses.
//
// Data sets (8.1): a four-data-set parameter holds data sets 1-4; data set 0 writes all four
// and reads succeed only while all four are equal (else error 9). A single parameter lives at
// data set 0 (1-4 give error 2). Writes to data sets 0-4 go to EEPROM and RAM and count as one
// EEPROM write each; 5-9 go to RAM only. Reads return the RAM image; a power cycle copies the
// EEPROM image back into RAM.

#include "core/objectdictionary.h"

#include <QHash>
#include <QSet>

namespace db::bonfiglioli {

class AcuStore
{
public:
    // One access's outcome: the data of a read, or the VABus error code (0 = none).
    struct Outcome
    {
        quint16 error = 0;
        QByteArray data;
    };

    // Parameters, types, access and limits from the description; values from its defaults.
    explicit AcuStore(const ObjectDictionary &description);

    bool knows(quint16 parameter) const { return m_params.contains(parameter); }
    bool hasDataSets(quint16 parameter) const;
    // The type a parameter is carried as (UNSIGNED16 for unknown ones).
    DataType type(quint16 parameter) const;

    Outcome read(quint16 parameter, quint8 dataSet) const;
    // running: the drive is in operation, so parameters marked lockedWhileRunning refuse (8).
    Outcome write(quint16 parameter, quint8 dataSet, const QByteArray &data, bool running = false);

    // Direct access for the simulator (both images; no checks). dataSet 0 of a four-data-set
    // parameter sets all four.
    void set(quint16 parameter, quint8 dataSet, const QVariant &raw);
    QVariant value(quint16 parameter, quint8 dataSet) const;
    // Raw limits enforced on writes, beyond the description's.
    void setLimits(quint16 parameter, const QVariant &min, const QVariant &max);
    void setLockedWhileRunning(quint16 parameter);
    // Longest string a parameter takes (99 unless set).
    void setMaxLength(quint16 parameter, int characters);

    // Values written to RAM only are lost.
    void powerCycle();
    quint64 eepromWrites() const { return m_eepromWrites; }
    // For EEPROM writes of values kept elsewhere (index parameters).
    void countEepromWrite() { ++m_eepromWrites; }

private:
    struct Param
    {
        DataType type = DataType::Unsigned16;
        bool dataSets = false;
        Access access = Access::ReadWrite;
        QVariant min;
        QVariant max;
        int maxLength = 99;
        bool lockedWhileRunning = false;
    };
    static quint32 key(quint16 parameter, quint8 dataSet)
    {
        return (quint32(parameter) << 8) | dataSet;
    }

    QHash<quint16, Param> m_params;
    QHash<quint32, QVariant> m_eeprom;
    QHash<quint32, QVariant> m_ram;
    quint64 m_eepromWrites = 0;
};

} // namespace db::bonfiglioli
