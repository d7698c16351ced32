#include "jogpanel.h"

#include "gearbox.h"
#include "motionblockbox.h"
#include "motionform.h"

#include "cia402/modes.h"
#include "devices/axisfactory.h"
#include "motion/motionchangelog.h"
#include "widgets/common/widgetstyle.h"

#include <QApplication>
#include <QDoubleSpinBox>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>

#include <cmath>

namespace db::widgets {

namespace {
// A unit for people: the drive's user-defined units ("units", "units/s") in the program's
// language, any other unit as the drive states it.
QString shownUnit(const QString &unit)
{
    if (unit.isEmpty())
        return JogPanel::tr("units");
    if (unit.startsWith(QLatin1String("units")))
        return JogPanel::tr("units") + unit.mid(5);
    return unit;
}
} // namespace

using namespace motion;

JogPanel::JogPanel(QWidget *parent)
    : QWidget(parent)
{
    setFocusPolicy(Qt::StrongFocus);
    buildUi();
    m_defaults = settings();
    m_keepAlive = new QTimer(this);
    m_keepAlive->setObjectName(QStringLiteral("keepAliveTimer"));
    m_keepAlive->setInterval(kKeepAliveMs);
    connect(m_keepAlive, &QTimer::timeout, this, [this] {
        if (m_motion)
            m_motion->keepAlive();
        if (m_cia && !m_cia->linkSupervision().isEmpty())
            renderSupervision(); // the time left when the drive stops answering
    });

    // Hold-to-run: press starts, release halts (QAbstractButton::released also fires when the
    // mouse leaves the button while pressed).
    connect(m_jogMinus, &QPushButton::pressed, this, [this] { startJog(-1); });
    connect(m_jogPlus, &QPushButton::pressed, this, [this] { startJog(+1); });
    connect(m_jogMinus, &QPushButton::released, this,
            [this] { stopJog(tr("jog button released")); });
    connect(m_jogPlus, &QPushButton::released, this,
            [this] { stopJog(tr("jog button released")); });
    connect(m_stepMinus, &QPushButton::clicked, this, [this] { stepJog(-1); });
    connect(m_stepPlus, &QPushButton::clicked, this, [this] { stepJog(+1); });
    connect(m_enableButton, &QPushButton::clicked, this, &JogPanel::enableDrive);
    connect(m_disableButton, &QPushButton::clicked, this, &JogPanel::disableDrive);
    connect(m_resetButton, &QPushButton::clicked, this, &JogPanel::resetFault);
    connect(m_stopReset, &QPushButton::clicked, this, &JogPanel::resetFault);
    connect(m_override, &QDoubleSpinBox::valueChanged, this, [this](double percent) {
        if (m_motion)
            m_motion->setVelocityOverride(percent);
    });
    connect(qApp, &QApplication::focusChanged, this, &JogPanel::onFocusChanged);
    render();
    renderLimits();
}

JogPanel::~JogPanel()
{
    teardown();
}

void JogPanel::teardown()
{
    // m_connection is already null when the connection is being destroyed: nothing to send.
    if (m_jogDirection != 0 && m_motion && m_connection)
        stopAll(tr("the panel let go of the drive"));
    for (const auto &c : m_connectionSignals)
        disconnect(c);
    m_connectionSignals.clear();
    m_keepAlive->stop();
    releaseSupervision();
    m_form->setLease(nullptr);
    m_form->setAxis(nullptr);
    m_blocks->setAxis(nullptr);
    m_gear->setAxis(nullptr);
    m_power.reset();
    m_reset.reset();
    m_lease.reset();
    m_motion.reset();
    m_cia.reset();
    m_jogDirection = 0;
    m_limitsKnown = false;
}

void JogPanel::setConnection(DeviceConnection *connection)
{
    // (m_connection is already null while its connection is being destroyed: tear down then.)
    if (connection == m_connection && (connection ? m_cia != nullptr : m_cia == nullptr))
        return;
    teardown();
    ++m_generation;
    keepSettingsFor(connection);
    m_connection = connection;
    setMessage({});
    if (!connection) {
        render();
        renderLimits();
        renderSupervision();
        return;
    }
    const ObjectDictionary &dict = connection->dictionary();
    auto made = devices::makeAxis(connection);
    if (!made) {
        m_connection = nullptr;
        setMessage(made.error().message(), style::errorColor());
        render();
        renderLimits();
        renderSupervision();
        return;
    }
    m_cia = std::move(made.value());
    m_positionUnit = shownUnit(m_cia->positionUnit());
    m_velocityUnit = m_cia->velocityUnit().isEmpty() ? m_positionUnit + QStringLiteral("/s")
                                                     : shownUnit(m_cia->velocityUnit());
    m_motion = std::make_unique<MotionAxis>(m_cia.get());
    m_motion->setWatchdogTimeout(kWatchdogMs);
    motion::recordCommands(m_motion.get(), m_changeLog, connection->uri().toString());
    m_motion->setVelocityOverride(m_override->value());
    m_power = std::make_unique<MotionCommand>(m_motion.get(), CommandKind::Power);
    m_reset = std::make_unique<MotionCommand>(m_motion.get(), CommandKind::Reset);
    m_lease = std::make_unique<LeasedMove>(m_motion.get());
    if (canopen::DriveSupervision::modeFor(connection) != canopen::DriveSupervision::Mode::None)
        m_driveSupervision = std::make_unique<canopen::DriveSupervision>(connection);
    m_form->setAxis(m_motion.get());
    m_form->setLease(m_lease.get());
    m_form->setFeatures(m_cia->features());
    // This drive's homing methods; none described: the default list, not the previous drive's.
    const ObjectDef *method = dict.find(cia402::obj::HomingMethod);
    m_form->setHomingMethods(method ? method->displayEnumeration() : QMap<qlonglong, QString>());

    connect(m_cia.get(), &AxisInterface::statusChanged, this, &JogPanel::render);
    connect(m_cia.get(), &AxisInterface::connectionLost, this, &JogPanel::onConnectionLost);
    connect(m_motion.get(), &MotionAxis::stateChanged, this, &JogPanel::render);
    connect(m_motion.get(), &MotionAxis::watchdogExpired, this, [this] {
        m_jogDirection = 0;
        noteStop(tr("deadman watchdog: the GUI stopped refreshing for %1 ms").arg(kWatchdogMs));
    });
    connect(m_lease.get(), &LeasedMove::ended, this, [this](MotionCommand::Status s) {
        m_jogDirection = 0; // at the limit or the step's end, refused or superseded
        if (s == MotionCommand::Status::Error)
            setMessage(tr("Jog: %1").arg(m_lease->command()->error().message()),
                       style::errorColor());
    });
    for (MotionCommand *c : { m_power.get(), m_reset.get() }) {
        connect(c, &MotionCommand::statusChanged, this, [this, c](MotionCommand::Status s) {
            if (s == MotionCommand::Status::Error)
                setMessage(tr("%1: %2").arg(c->name(), c->error().message()), style::errorColor());
        });
    }
    m_connectionSignals << connect(
        connection, &DeviceConnection::stateChanged, this, [this](DeviceConnection::State state) {
            if (state == DeviceConnection::State::Connected && !m_limitsKnown)
                onInitialized(nullptr, m_generation);
            render();
        });
    m_connectionSignals << connect(connection, &QObject::destroyed, this,
                                   [this] { setConnection(nullptr); });
    m_connectionSignals << connect(connection, &DeviceConnection::supervisionLost, this,
                                   &JogPanel::onSupervisionLost);
    m_keepAlive->start();
    if (connection->isConnected())
        onInitialized(nullptr, m_generation);
    render();
    renderLimits();
    renderSupervision();
}

void JogPanel::onInitialized(Reply *reply, quint64 generation)
{
    if (generation != m_generation || !m_cia)
        return;
    if (!reply) {
        // Factor group and supported modes first; the limits need the scaling.
        Reply *r = m_cia->initialize();
        connect(r, &Reply::finished, this, [this, r, generation] {
            r->deleteLater();
            onInitialized(r, generation);
        });
        return;
    }
    if (!reply->ok()
        && (reply->error().kind() == Error::Kind::Timeout
            || reply->error().kind() == Error::Kind::Disconnected)) {
        // Nothing answered: no limits from a drive that never replied (the description's
        // defaults are not the drive's values). Read again once it answers.
        m_limits->setText(tr("The drive did not answer: its limits are not known yet."));
        return;
    }
    // What the drive said about itself: its units, modes and limits.
    m_positionUnit = shownUnit(m_cia->positionUnit());
    m_velocityUnit = m_cia->velocityUnit().isEmpty() ? m_positionUnit + QStringLiteral("/s")
                                                     : shownUnit(m_cia->velocityUnit());
    m_form->setFeatures(m_cia->features());
    m_blocks->setAxis(m_motion.get());
    m_gear->setAxis(m_motion.get());
    if (!m_cia->featureNote().isEmpty())
        setMessage(m_cia->featureNote());
    applyLimits();
}

bool JogPanel::isMotionInProgress() const
{
    if (!m_motion)
        return false;
    if (m_jogDirection != 0)
        return true;
    const AxisState st = m_motion->state();
    if (st == AxisState::DiscreteMotion || st == AxisState::ContinuousMotion
        || st == AxisState::SynchronizedMotion || st == AxisState::Homing
        || st == AxisState::Stopping)
        return true;
    const AxisInterface::Status s = m_cia->status();
    return s.valid && (s.moving || std::abs(s.velocity) > m_config.velocityWindow);
}

// ---- power ---------------------------------------------------------------------------------

void JogPanel::runPower(CommandKind kind, bool enable)
{
    MotionCommand *c = kind == CommandKind::Reset ? m_reset.get() : m_power.get();
    if (!c)
        return;
    c->setEnable(enable);
    c->setExecute(false);
    c->setExecute(true);
}

void JogPanel::enableDrive()
{
    setMessage({});
    if (!m_driveSupervision || m_driveSupervision->isArmed()) {
        runPower(CommandKind::Power, true);
        return;
    }
    // Drive-side supervision before the power stage goes on. If the drive refuses it, the
    // drive is enabled all the same (the lease still bounds every jog) and the panel says so.
    Reply *r = m_driveSupervision->arm();
    const quint64 generation = m_generation;
    connect(r, &Reply::finished, this, [this, r, generation] {
        r->deleteLater();
        if (generation != m_generation)
            return;
        renderSupervision();
        runPower(CommandKind::Power, true);
        if (!r->ok())
            setMessage(r->error().message(), style::warningColor());
    });
}

void JogPanel::disableDrive()
{
    m_jogDirection = 0;
    runPower(CommandKind::Power, false);
    if (m_driveSupervision && m_driveSupervision->isArmed()) {
        Reply *r = m_driveSupervision->disarm();
        connect(r, &Reply::finished, this, [this, r] {
            r->deleteLater();
            renderSupervision();
            if (!r->ok())
                setMessage(r->error().message(), style::warningColor());
        });
    }
}

void JogPanel::resetFault()
{
    setMessage({});
    runPower(CommandKind::Reset, true);
}

// ---- jog -----------------------------------------------------------------------------------

MoveParams JogPanel::jogParams() const
{
    MoveParams p;
    p.velocity = m_jogVelocity->value();
    p.acceleration = p.deceleration = m_jogAcceleration->value();
    p.jerk = m_config.maxJerk; // no jerk field for jogging: the axis maximum (never zero, R5)
    return p;
}

void JogPanel::startJog(int direction)
{
    if (!m_lease || direction == 0 || m_jogDirection == direction)
        return;
    setMessage({});
    m_jogDirection = direction > 0 ? 1 : -1;
    m_lease->jog(m_jogDirection, jogParams());
    m_motion->keepAlive();
}

void JogPanel::stopJog(const QString &reason)
{
    if (m_jogDirection == 0 || !m_lease)
        return;
    m_jogDirection = 0;
    m_lease->halt();
    noteStop(reason);
}

void JogPanel::stepJog(int direction)
{
    if (!m_lease)
        return;
    setMessage({});
    m_jogDirection = 0;
    m_lease->step(direction * m_stepSize->value(), jogParams());
}

void JogPanel::stopAll(const QString &reason)
{
    if (!isMotionInProgress())
        return;
    m_jogDirection = 0;
    m_lease->stopRenewing();
    m_motion->stopNow();
    noteStop(reason);
}

void JogPanel::noteStop(const QString &reason)
{
    m_lastStopReason = reason;
    if (m_motion && m_motion->state() == AxisState::ErrorStop)
        setMessage(tr("Stopped: %1. The axis is in ErrorStop now and takes no motion command "
                      "until it is reset: click Reset.")
                       .arg(reason),
                   style::warningColor());
    else
        setMessage(tr("Stopped: %1").arg(reason), style::warningColor());
    render(); // the ErrorStop note names this reason
    Q_EMIT stopped(reason);
}

// ---- safety stops --------------------------------------------------------------------------

void JogPanel::onConnectionLost(const Error &error)
{
    // The MotionAxis has failed the running command; nothing can reach the drive any more.
    const bool wasMoving = m_jogDirection != 0 || isMotionInProgress();
    m_jogDirection = 0;
    if (wasMoving)
        noteStop(tr("connection lost (%1); the drive may still be moving").arg(error.message()));
    else
        setMessage(tr("Connection lost: %1").arg(error.message()), style::errorColor());
    render();
}

void JogPanel::onSupervisionLost(const QString &reason)
{
    if (isMotionInProgress())
        stopAll(reason);
    else
        setMessage(reason, style::errorColor());
}

void JogPanel::onFocusChanged(QWidget *, QWidget *now)
{
    if (m_jogDirection != 0 && now != this && !isAncestorOf(now))
        stopJog(tr("focus left the jog panel"));
}

void JogPanel::keyPressEvent(QKeyEvent *event)
{
    const int key = event->key();
    const int direction = (key == Qt::Key_Left || key == Qt::Key_Minus) ? -1
        : (key == Qt::Key_Right || key == Qt::Key_Plus)                 ? +1
                                                                        : 0;
    if (key == Qt::Key_Escape) {
        stopAll(tr("Esc"));
        event->accept();
        return;
    }
    if (direction == 0) {
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
    if (!event->isAutoRepeat())
        startJog(direction);
}

void JogPanel::keyReleaseEvent(QKeyEvent *event)
{
    const int key = event->key();
    if (key != Qt::Key_Left && key != Qt::Key_Right && key != Qt::Key_Minus
        && key != Qt::Key_Plus) {
        QWidget::keyReleaseEvent(event);
        return;
    }
    event->accept();
    if (!event->isAutoRepeat())
        stopJog(tr("jog key released"));
}

void JogPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::ActivationChange && !isActiveWindow())
        stopJog(tr("window deactivated"));
    QWidget::changeEvent(event);
}

void JogPanel::hideEvent(QHideEvent *event)
{
    stopJog(tr("jog panel hidden"));
    QWidget::hideEvent(event);
}

} // namespace db::widgets
