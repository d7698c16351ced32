#pragma once

// One simulated NM170/NM172/NM174 display on a CAN bus: the CANopen slave as the device
// implements it (SDO server with its abort codes, NMT with boot-up, heartbeat producer and
// consumer, EMCY with the sub-code in byte 7, TxPDO1/TxPDO2 on change with inhibit time, on SYNC
// or cyclic, RxPDO1 broadcast on 201h, RxPDO2 with the control-word check, LSS with the
// device's broadcast addressing) and its application: the spindle model (spindle.h) stepped by
// the 10 ms internal cycle, and SDO writes whose effects reach the application one per cycle
// through a 50-entry queue, as the device's two controllers do.
//
// Bus-agnostic: frames in through receive(), out through transmit(). The operator's hand is
// turnShaft() and pressKey(); in broadcast addressing either one takes the offered node id.

#include "devices/nm17x/nm17xdescription.h"
#include "spindle.h"

#include "canopen/device/errorcontrolslave.h"
#include "canopen/device/lssslave.h"
#include "canopen/device/sdoserver.h"
#include "canopen/device/simulatednode.h"

#include <QCanBusFrame>
#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QQueue>
#include <QTimer>

#include <array>
#include <memory>

namespace db::nm17x {

class SimulatedNm17x : public QObject, public canopen::ObjectAccess
{
    Q_OBJECT
public:
    static constexpr int kCycleMs = 10;
    static constexpr int kWriteQueueSize = 50;

    SimulatedNm17x(Variant variant, quint32 serial, canopen::NodeId node = kDeliveryNodeId,
                   QObject *parent = nullptr);
    ~SimulatedNm17x() override;

    Variant variant() const { return m_variant; }
    quint32 serial() const { return m_serial; }
    canopen::NodeId nodeId() const { return m_node; }
    canopen::NmtState nmtState() const { return m_state; }
    // Changes through this reference are picked up by the next cycle.
    Spindle &spindle()
    {
        wake();
        return m_spindle;
    }
    // Whether the 10 ms cycle runs: it stops while a cycle would change nothing and starts again
    // with a frame the display acts on, an operator action or a change to the spindle.
    bool cycling() const { return m_cycle.isActive(); }
    bool inAddressingMode() const { return m_addressing; }
    // The node id offered by broadcast addressing and shown on the display (0 = none).
    quint8 offeredNodeId() const { return m_offered; }
    // Oscillating between D1 and D2 (2045h:01/02), started by 204Dh:02 = 1 or the inputs.
    bool isOscillating() const { return m_oscillating; }
    // The external inputs F and G (motor cable pins F/G), as the operator's switch sets them;
    // their function follows 2041h:03 (spec 6.10): 0 standard (one input: travel, both:
    // oscillation), 1 Takten (F: D1, G: D2), 2 ExternPosi (F: D3 while held), 3 off.
    void setInputs(bool f, bool g);
    qint32 position() const; // 6004h, as the jump filter passed it
    // A disturbed sensor (NM170/NM172 multiturn, NM174 SSI): its readings are off by `steps`
    // (unscaled) for `readings` readings of the 10 ms cycle, or for good when readings is 0 (the
    // sensor slipped). The jump filter (2005h:01/02) decides what the display takes.
    void disturbSensor(double steps, int readings);
    bool sensorDisturbed() const { return m_glitchSteps != 0; }
    // Jumps the filter discarded since power-on.
    int filteredJumps() const { return m_filteredJumps; }
    quint16 statusWord() const; // 204Eh:01
    quint16 errorWord() const; // 204Eh:02

    // Power on: boot-up, Pre-operational (Operational with 1F80h = 8), the 10 ms cycle starts.
    void start();
    void receive(const QCanBusFrame &frame);

    // The operator's hand (1/100 mm of travel); selects the device in broadcast addressing.
    void turnShaft(double delta);
    // A device key (right = +1 counting up, left = -1); short presses jog one step, a key during
    // an automatic positioning aborts it. Selects the device in broadcast addressing.
    void pressKey(int direction, int ms = 100);

    // ---- ObjectAccess (the SDO server's view) ----
    const ObjectDictionary &dictionary() const override { return m_serverView; }
    Result<QVariant> read(ObjectAddress address) override;
    Result<void> write(ObjectAddress address, const QVariant &raw) override;

Q_SIGNALS:
    void transmit(const QCanBusFrame &frame);
    void nodeIdChanged(db::canopen::NodeId node);

private:
    // ---- communication (simulatednm17x.cpp) ----
    void bootUp();
    void resetNode(bool application);
    void setState(canopen::NmtState state);
    void handleNmt(const QByteArray &d);
    void handleLss(const QCanBusFrame &frame);
    bool selectForAddressing();
    void lssAnswer(quint8 cs, quint8 code);
    void cycle();
    bool resting() const;
    void wake();
    std::array<QByteArray, 2> tpdoPayloads() const;
    void sendTpdos(bool sync);
    void raiseEmergency(quint16 code, quint8 subCode);
    void send(quint32 id, const QByteArray &data);
    quint32 u32(ObjectAddress address) const;
    void setValue(ObjectAddress address, const QVariant &raw);
    void applyNodeId(canopen::NodeId node);

    // ---- application (simulatednm17x_app.cpp) ----
    Result<void> checkWrite(ObjectAddress address, const QVariant &raw);
    void applyWrite(ObjectAddress address, const QVariant &raw);
    void handleBroadcast(const QByteArray &d);
    void handleRpdo2(const QByteArray &d);
    void startSetpoint(qint32 target, bool release, bool loop, std::optional<Speed> speed);
    void setCorrection(qint16 correction);
    void setOscillation(bool on, bool byInputs = false);
    // Takten with one input active, or ExternPosi with F active: CAN setpoints and drive commands
    // are ignored.
    bool inputsOwnAxis() const;
    quint16 inputStatus() const; // status bits 3 and 4
    void followExternPosi(); // in the cycle: the release ends at the target
    void oscillate(); // the next leg, when the last one has ended
    SpindleSettings settings() const;
    void readSensor(); // one reading through the jump filter, every cycle
    double stepsToPosition(double steps) const; // by the scaling 2004h
    void applyScaling(quint32 scaling);

    Variant m_variant;
    quint32 m_serial;
    canopen::NodeId m_node;
    ObjectDictionary m_dictionary; // with ranges: the device checks them itself
    ObjectDictionary m_serverView; // without ranges, so that the server leaves them to us
    std::unique_ptr<canopen::ObjectValueStore> m_store;
    QHash<ObjectAddress, QVariant> m_flash; // communication objects saved by 1010h
    bool m_restorePending = false; // 1011h "load": defaults at the next reset
    canopen::SdoServer m_sdo;
    canopen::LssSlave m_lss;
    canopen::ErrorControlSlave m_errorControl;
    canopen::NmtState m_state = canopen::NmtState::BootUp;
    bool m_started = false;
    QTimer m_cycle;
    QElapsedTimer m_restClock;
    QTimer m_heartbeat;
    Spindle m_spindle;
    double m_presetOffset = 0; // part of the spindle position set by presets (6003h)
    quint32 m_scaling = 1736111; // 2004h as the application uses it
    // The jump filter: the sensor's disturbance (steps), the part of it the filter accepted,
    // and how many jumps in a row it discarded.
    double m_glitchSteps = 0;
    int m_glitchReadings = 0; // readings left, 0 = for good
    double m_acceptedGlitch = 0;
    int m_discarded = 0;
    int m_filteredJumps = 0;
    QQueue<std::pair<ObjectAddress, QVariant>> m_writes; // effects waiting for the cycle
    // TxPDO state per PDO (0 = TxPDO1, 1 = TxPDO2)
    QByteArray m_lastTpdo[2];
    int m_sinceTpdoMs[2] = { 1 << 20, 1 << 20 };
    int m_syncCount[2] = { 0, 0 };
    // LSS broadcast addressing
    int m_broadcastStep = 0; // 40h EC, 41h/42h/43h FFFFFFFF seen in order
    bool m_addressing = false;
    bool m_addressedByBroadcast = false; // took its id; ignores further node ids
    quint8 m_offered = 0;
    bool m_showNodeId = false; // 2008h
    bool m_oscillating = false;
    bool m_towardsD2 = true; // the leg in progress
    bool m_inputF = false;
    bool m_inputG = false;
    bool m_d3Released = false; // D3 written since its last use (locked after power-on)
    bool m_externPosiRunning = false;
    int m_keyDown = 0; // a key held (+1 right, -1 left), 0 none
};

} // namespace db::nm17x
