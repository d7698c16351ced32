#pragma once

#include "cia402/statusword.h"
#include "core/deviceconnection.h"

#include <QHash>
#include <QPointer>
#include <QSet>
#include <QTimer>
#include <QWidget>

class QLabel;

namespace db::widgets {

class Lamp;

// The live status of a CiA 402 drive (movingcap.md 5, 7, 8.1): PDS state, statusword bits, mode,
// actual values, faults (1002h bits, 603Fh with its text) and the digital I/O.
//
// Polling contract: one cycle reads every object in polledObjects(); the next cycle starts
// pollInterval() ms after the last reply of the previous one finished, so a slow device is never
// flooded. Polling runs only while the connection is Connected and the panel is visible. Failed
// reads leave the old value greyed out (stale) with the error as tool tip; nothing pops up.
class DriveStatusPanel : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kDefaultPollIntervalMs = 200;
    static constexpr int kInputCount = 10; // IN1..IN10 = 60FDh bits 16..25 (movingcap.md 8.1)
    static constexpr int kOutputCount = 4; // OUT1..OUT4 = 60FEh.1 bits 16..19

    explicit DriveStatusPanel(QWidget *parent = nullptr);

    // May be null. The panel does not own the connection and copes with its destruction.
    void setConnection(DeviceConnection *connection);
    DeviceConnection *connection() const { return m_connection; }

    int pollInterval() const { return m_intervalMs; }
    void setPollInterval(int ms);
    bool isPolling() const { return m_timer.isActive() || m_pending > 0; }

    // The objects read every cycle: 6041h, 6061h, 6064h, 606Ch, 6078h, 1002h, 603Fh, 60FDh,
    // 60FEh.1.
    static QList<ObjectAddress> polledObjects();
    // The last raw value read (invalid before the first successful read).
    QVariant value(ObjectAddress address) const { return m_values.value(address); }
    bool isStale(ObjectAddress address) const { return !m_fresh.contains(address); }

    // The CiA 402 state name as shown ("Operation enabled"), translated.
    static QString stateText(cia402::State state);

Q_SIGNALS:
    // After every completed poll cycle, whether all reads succeeded or not.
    void cycleFinished();

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void buildUi();
    void onStateChanged();
    void scheduleNext(int delayMs);
    void startCycle();
    void onReplyFinished(class Reply *reply, quint64 generation);
    void render();
    void renderState();
    void renderValues();
    void renderFaults();
    void renderIo();
    void markAllStale();
    QString valueText(ObjectAddress address) const;

    QPointer<DeviceConnection> m_connection;
    QList<QMetaObject::Connection> m_connectionSignals;
    QTimer m_timer;
    int m_intervalMs = kDefaultPollIntervalMs;
    int m_pending = 0;
    quint64 m_generation = 0;
    QHash<ObjectAddress, QVariant> m_values;
    QHash<ObjectAddress, QString> m_errors;
    QSet<ObjectAddress> m_fresh;

    QLabel *m_stateLabel = nullptr;
    QLabel *m_statuswordLabel = nullptr;
    QLabel *m_modeLabel = nullptr;
    QList<Lamp *> m_bitLamps;
    QLabel *m_positionLabel = nullptr;
    QLabel *m_velocityLabel = nullptr;
    QLabel *m_currentLabel = nullptr;
    QLabel *m_registerLabel = nullptr;
    QLabel *m_registerBitsLabel = nullptr;
    QLabel *m_warningBitsLabel = nullptr;
    QLabel *m_lastErrorLabel = nullptr;
    QLabel *m_lastErrorText = nullptr;
    QList<Lamp *> m_inputLamps;
    QList<Lamp *> m_outputLamps;
    QLabel *m_footer = nullptr;
};

} // namespace db::widgets
