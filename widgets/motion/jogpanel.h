#pragma once

#include "canopen/drivesupervision.h"
#include "core/changelog.h"
#include "core/deviceconnection.h"
#include "motion/axisinterface.h"
#include "motion/leasedmove.h"
#include "motion/motionaxis.h"

#include <QHash>
#include <QPointer>
#include <QTimer>
#include <QVariantMap>
#include <QWidget>

#include <memory>

class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace db::widgets {

class Lamp;
class GearBox;
class MotionBlockBox;
class MotionForm;

// Moving an axis by hand: enable/disable/reset, hold-to-run jog (buttons and keys),
// step jog, the motion command form, status lamps, live position/velocity and the drive's
// limits. The panel gets the device's axis from the axis factory (devices/axisfactory.h) and
// builds a MotionAxis on it; it never creates transports.
//
// Jog: while a jog button or key (Left/Minus, Right/Plus; auto-repeat ignored) is held, the
// axis moves by leases (motion::LeasedMove): profile position moves from the actual position,
// each covering LeasedMove::kLeaseMs at the jog velocity plus the braking distance, renewed every
// LeasedMove::kRenewMs, never past the software limits. Release halts it with the jog
// deceleration (MC_Halt). A step is a leased move of the step size.
//
// Safety contract: a running jog halts on button or key release, on window deactivation, when
// the focus leaves the panel and when the panel is hidden. stopAll() (Esc, wired application-
// wide by the main window) quick-stops any motion. A lost connection or, for CANopen, a lost
// heartbeat of the node quick-stops and fails the running command with the cause. The
// MotionAxis deadman watchdog runs with kWatchdogMs; the panel's keep-alive timer (every
// kKeepAliveMs, object name "keepAliveTimer") feeds it, so an event loop that stops turning
// quick-stops the drive. If nothing reaches the drive any more (process killed, PC asleep,
// cable pulled) the lease runs out on the drive: it brakes and stands at most
// LeasedMove::leaseTimeMs() after the last renewal it took. On CANopen, Enable first arms the
// drive-side supervision (canopen::DriveSupervision: heartbeat or node guarding, 6007h quick
// stop), Disable restores the drive's previous settings; the label "supervision" says what is
// active. Every stop names its reason in lastStopReason() and stopped().
class JogPanel : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kWatchdogMs = 300;
    static constexpr int kKeepAliveMs = 100;
    static constexpr double kDefaultJogVelocity = 500.0;
    static constexpr double kDefaultJogAcceleration = 5000.0;
    static constexpr double kDefaultStep = 100.0;

    explicit JogPanel(QWidget *parent = nullptr);
    ~JogPanel() override;

    // May be null. The connection is not owned; the panel copes with its destruction.
    void setConnection(DeviceConnection *connection);
    DeviceConnection *connection() const { return m_connection; }
    motion::MotionAxis *motionAxis() const { return m_motion.get(); }
    // Commands of the axes the panel makes from now on are recorded there (null: none).
    void setChangeLog(ChangeLog *log) { m_changeLog = log; }
    // The device's axis; null without a connection or when the device has none.
    motion::AxisInterface *axis() const { return m_cia.get(); }
    motion::LeasedMove *leasedMove() const { return m_lease.get(); }
    // Null unless the connection's drive offers heartbeat consumption or node guarding.
    canopen::DriveSupervision *supervision() const { return m_driveSupervision.get(); }
    MotionForm *motionForm() const { return m_form; }
    // Limits read from the drive by its axis once it answered. When none of the axis's reads
    // were answered nothing is limited by them and they are read again when the device answers
    // (setDeviceResponding(true)).
    bool limitsKnown() const { return m_limitsKnown; }
    // Whether the device answers requests (the main window's ConnectionHealth). While it does
    // not, Enable, Jog and Step are disabled and the state shows why. True until told otherwise.
    void setDeviceResponding(bool responding, const QString &why = {});
    bool isDeviceResponding() const { return m_responding; }

    // +1 or -1 while a jog runs, else 0.
    int jogDirection() const { return m_jogDirection; }
    bool isMotionInProgress() const;
    QString lastStopReason() const { return m_lastStopReason; }
    // While the axis is in ErrorStop: what stopped it and the way out (the Drive Status page
    // shows the same, motionNoteChanged()); empty otherwise.
    QString motionNote() const { return m_motionNote; }

public Q_SLOTS:
    void enableDrive();
    void disableDrive();
    void resetFault();
    void startJog(int direction);
    // Hold-to-run released: halts a running jog with the ramp. No-op without a jog.
    void stopJog(const QString &reason);
    void stepJog(int direction);
    // Quick stop of any motion; no-op when nothing moves (so Esc in a dialog stays harmless).
    void stopAll(const QString &reason);

Q_SIGNALS:
    void stopped(const QString &reason);
    void motionNoteChanged(const QString &note);

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void buildUi();
    void teardown();
    void onInitialized(Reply *reply, quint64 generation);
    void applyLimits();
    void onConnectionLost(const Error &error);
    void onSupervisionLost(const QString &reason);
    void onFocusChanged(QWidget *old, QWidget *now);
    void runPower(motion::CommandKind kind, bool enable);
    void render();
    void renderLimits();
    void renderSupervision();
    void releaseSupervision();
    void setMessage(const QString &text, const QColor &color = {});
    void noteStop(const QString &reason);
    motion::MoveParams jogParams() const;

    QPointer<DeviceConnection> m_connection;
    std::unique_ptr<motion::AxisInterface> m_cia;
    std::unique_ptr<motion::MotionAxis> m_motion;
    QPointer<ChangeLog> m_changeLog;
    std::unique_ptr<motion::MotionCommand> m_power;
    std::unique_ptr<motion::MotionCommand> m_reset;
    std::unique_ptr<motion::LeasedMove> m_lease; // jog and step
    std::unique_ptr<canopen::DriveSupervision> m_driveSupervision;
    QList<QMetaObject::Connection> m_connectionSignals;
    quint64 m_generation = 0; // which connection a late reply belongs to
    bool m_limitsKnown = false;
    bool m_responding = true;
    QString m_silentWhy;
    motion::AxisConfig m_config;
    QString m_positionUnit;
    QString m_velocityUnit;
    int m_jogDirection = 0;
    QString m_lastStopReason;
    QTimer *m_keepAlive = nullptr; // child "keepAliveTimer"

    QPushButton *m_enableButton = nullptr;
    QPushButton *m_disableButton = nullptr;
    QPushButton *m_resetButton = nullptr;
    QLabel *m_state = nullptr;
    QLabel *m_position = nullptr;
    QLabel *m_velocity = nullptr;
    QLabel *m_message = nullptr;
    QPushButton *m_stopReset = nullptr; // "stopReset": leaves ErrorStop in one click
    QList<Lamp *> m_lamps;
    QDoubleSpinBox *m_jogVelocity = nullptr;
    QDoubleSpinBox *m_jogAcceleration = nullptr;
    QDoubleSpinBox *m_stepSize = nullptr;
    QDoubleSpinBox *m_override = nullptr;
    // Motion settings (form and jog fields) per device URI, so that one drive's limits never
    // stay on another's values; m_settingsKey is the device whose values are shown.
    QVariantMap settings() const;
    void applySettings(const QVariantMap &values);
    void keepSettingsFor(DeviceConnection *next);
    QHash<QString, QVariantMap> m_kept;
    QVariantMap m_defaults;
    QString m_settingsKey;
    QString m_motionNote;
    QPushButton *m_jogMinus = nullptr;
    QPushButton *m_jogPlus = nullptr;
    QPushButton *m_stepMinus = nullptr;
    QPushButton *m_stepPlus = nullptr;
    QLabel *m_limits = nullptr;
    QLabel *m_supervision = nullptr;
    MotionForm *m_form = nullptr;
    MotionBlockBox *m_blocks = nullptr; // drives with a motion block table
    GearBox *m_gear = nullptr; // drives with an electronic gear
};

} // namespace db::widgets
