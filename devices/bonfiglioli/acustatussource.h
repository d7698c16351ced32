#pragma once

#include "core/statussource.h"

namespace db::bonfiglioli {

// The status of an ACTIVE Cube ACU over VABus/TCP: the state from status word 411 (mask 0x006F),
// the current fault 260 written as the fault table writes it ("F2714") with its text, the
// warnings 270 and 274 by name, parameter 388 (what the inverter does when the link stops) and
// the actual values the description has (stator frequency 210, RMS current 211, active power
// 213, actual speed 240, internal reference frequency 228, active data set 249).
//
// On a VABus connection a cycle is one telegram: the source joins the connection's block reader
// (GroupReader, the one owner of the block definition 17) with its parameters and reads them
// with 19; the reader writes the definition when needed (first use, reconnect, reset inverter).
// What the block does not hold (parameters from 1000 on, a full block) is read on its own after
// it, and so is everything on other connections or after the inverter refused the definition
// GroupReader::kMaxFailures times. Polling never writes EEPROM.
class AcuStatusSource : public StatusSource
{
    Q_OBJECT
public:
    explicit AcuStatusSource(DeviceConnection *connection, QObject *parent = nullptr);

    QString statusWordLabel() const override;
    QList<StatusLamp> lamps() const override;
    QList<ObjectAddress> polledObjects() const override { return m_objects; }
    QList<StatusValue> actualValues() const override;
    StatusValue fault() const override;
    QString faultText() const override;
    bool faultActive() const override;
    QStringList warnings() const override;
    QString linkLossText() const override;

    // "F2714" for 0x2714.
    static QString faultName(quint32 code);
    // The last cycle read the polled parameters as one block (false before the first cycle,
    // after the device refused the block, and on connections without block access).
    bool usesBlock() const { return m_usedBlock; }
    // Block definitions written (parameter 17) on the connection, by whoever joined the block.
    int blockDefinitions() const;

protected:
    void poll() override;

private:
    QList<ObjectAddress> m_objects;
    QList<ObjectAddress> m_actualValues;
    QList<ObjectAddress> m_joined; // what the block reader was last asked to hold
    bool m_usedBlock = false;
};

} // namespace db::bonfiglioli
