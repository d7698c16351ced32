#pragma once

#include "core/statussource.h"

namespace db::bonfiglioli {

// The status of an ACTIVE Cube ACU over VABus/TCP: the state from status word 411 (mask 0x006F),
// the current fault 260 written as the fault table writes it ("F2714") with its text, the
// warnings 270 and 274 by name, parameter 388 (what the inverter does when the link stops) and
// the actual values the description has (stator frequency 210, RMS current 211, active power
// 213, actual speed 240, internal reference frequency 228, active data set 249).
//
// On a VABus connection a cycle is one telegram: the parameters are defined as a block (write 17,
// RAM only: the definition is volatile) once per connection and read with 19. A device error on
// 19 (e.g. the inverter was reset and lost the definition) defines the block again in the next
// cycle; after kMaxBlockFailures failed definitions in a row, and on other connections, every
// parameter is read on its own. What a block cannot hold (a holder's parameters from 1000 on) is
// read on its own after the block. Polling never writes EEPROM.
class AcuStatusSource : public StatusSource
{
    Q_OBJECT
public:
    static constexpr int kMaxBlockFailures = 3;

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
    // The polled parameters are read as one block (false before the first definition, after
    // giving up, and on connections without block access).
    bool usesBlock() const { return m_blockDefined && m_blockUsable; }
    // Block definitions written (parameter 17) since the source was made.
    int blockDefinitions() const { return m_definitions; }

protected:
    void poll() override;
    void connectionMade() override;

private:
    // `objects`: what this cycle reads; the block holds those that fit.
    void defineBlock(const QList<ObjectAddress> &objects);
    void readBlock(const QList<ObjectAddress> &objects);

    QList<ObjectAddress> m_objects;
    QList<ObjectAddress> m_actualValues;
    bool m_blockUsable = false;
    bool m_blockDefined = false;
    QList<ObjectAddress> m_blockAddresses; // what the defined block holds, in order
    int m_blockFailures = 0;
    int m_definitions = 0;
};

} // namespace db::bonfiglioli
