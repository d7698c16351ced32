#pragma once

// A simulated ACTIVE Cube ACU with a CM-VABus/TCP module, for demos and tests: the parameter
// memory (AcuStore, preset with the parameter table's defaults and the values of the VABus
// examples), the PLC port (vabus::Server), the 10 s communication watchdog with the reactions of
// parameter 388, block access (17/18/19), the network parameters (1431-1437), warnings and
// faults, and system bus slaves behind the module.

#include "acuindexed.h"
#include "acumotion.h"
#include "acustore.h"
#include "core/result.h"
#include "vabus/device/vabusserver.h"

#include <QMap>
#include <QObject>
#include <QTimer>

#include <memory>

namespace db::bonfiglioli {

class SimulatedAcu : public QObject, public vabus::DeviceHandler
{
    Q_OBJECT
public:
    static constexpr int kWatchdogMs = 10000;

    explicit SimulatedAcu(QObject *parent = nullptr);
    ~SimulatedAcu() override;

    // Serves the PLC port on 127.0.0.1:port (0 = chosen by the OS).
    Result<void> listen(quint16 port = 0);
    quint16 port() const;
    vabus::Server &server() { return m_server; }

    // Time without exchange after which the reaction of 388 follows (armed by the first
    // exchange).
    void setWatchdogMs(int ms);
    int watchdogMs() const { return m_watchdog.interval(); }
    bool isWatchdogArmed() const { return m_watchdog.isActive(); }

    // The module initialises for up to 20 s after power-on; until ms from now pass nothing is
    // answered (0 ends the wait).
    void setStartupDelayMs(int ms);
    bool isStarting() const { return m_starting.isActive(); }

    // A system bus slave with this node id (1-63) answers SYS 0x40 + id.
    void addSystemBusSlave(quint8 nodeId);

    AcuStore &store() { return m_store; }
    quint64 eepromWrites() const { return m_store.eepromWrites(); }
    // RAM values, the block definition and the fault are lost; the watchdog disarms.
    void powerCycle();
    // Switched off and on: the PLC connection drops, the port refuses connections for offMs
    // (power off and the module starting up), then the inverter runs as after powerCycle().
    // Returns at once.
    void restart(int offMs);
    // A cut cable: the PLC connection is aborted (the inverter keeps running, its link watchdog
    // counts on) and the port listens again at once. Returns the connections aborted (0 or 1).
    int dropClient();

    // The state machine, the simulated inputs (mains, STO, limit switches) and the axis.
    AcuMotion &motion() { return m_motion; }

    // Status (411) and diagnostics (260, 270, 274).
    quint16 statusWord() const;
    bool isRunning() const { return m_motion.isRunning(); }
    quint16 fault() const { return m_motion.fault(); }
    // Control word writes that went to a RAM data set (5) and to the EEPROM one (0).
    quint64 controlWritesRam() const { return m_controlWritesRam; }
    quint64 controlWritesEeprom() const { return m_controlWritesEeprom; }
    void raiseFault(quint16 code); // e.g. 0x2714 for F2714
    void setWarnings(quint16 bits); // 270 without bit 15 (which follows 274)
    void setApplicationWarnings(quint16 bits); // 274
    void setWarning2(bool on); // status bit 15

    std::optional<vabus::Telegram> handle(const vabus::Telegram &request) override;

Q_SIGNALS:
    // The watchdog fired; reaction is parameter 388's value.
    void communicationLost(int reaction);
    void logLine(const QString &line);

private:
    AcuStore::Outcome access(AcuStore &store, const vabus::Telegram &request);
    AcuStore::Outcome special(const vabus::Telegram &request, bool *handled);
    AcuStore::Outcome writeControlWord(const vabus::Telegram &request);
    AcuStore::Outcome writeMode(const vabus::Telegram &request, bool *handled);
    AcuStore::Outcome writeBlockDefinition(const QByteArray &data);
    AcuStore::Outcome readBlock();
    AcuStore::Outcome writeBlock(const QByteArray &data);
    AcuStore::Outcome ipCommand(const QByteArray &data);
    void onWatchdog();
    void presetValues(AcuStore &store, quint8 nodeId);
    void presetBlocks();

    struct BlockItem
    {
        quint16 parameter;
        quint8 dataSet;
    };

    AcuStore m_store;
    AcuIndexed m_indexed;
    AcuMotion m_motion;
    QMap<quint8, std::shared_ptr<AcuStore>> m_slaves;
    vabus::Server m_server;
    QTimer m_watchdog;
    QTimer m_starting;
    QList<BlockItem> m_block; // block definition (17), volatile
    QMap<quint16, QList<QVariant>> m_activeIp; // 1432-1435 as applied (octets 1-4)
    quint64 m_controlWritesRam = 0;
    quint64 m_controlWritesEeprom = 0;
    quint16 m_warnings = 0;
    quint16 m_appWarnings = 0;
    quint16 m_lastError = 0;
    bool m_warning2 = false;
};

} // namespace db::bonfiglioli
