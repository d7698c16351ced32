#include "commands_motion.h"
#include "commands_motion_p.h"

#include "canopen/drivesupervision.h"
#include "devices/axisfactory.h"
#include "motion/leasedmove.h"
#include "motion/motionaxis.h"

#include <QCoreApplication>
#include <QDeadlineTimer>

#include <functional>
#include <memory>
#include <optional>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

using namespace motion;

namespace motioncmd {

const QString kAbs = QStringLiteral("abs");
const QString kRel = QStringLiteral("rel");
const QString kAdd = QStringLiteral("add");
const QString kVel = QStringLiteral("vel");
const QString kAcc = QStringLiteral("acc");
const QString kDec = QStringLiteral("dec");
const QString kTime = QStringLiteral("time");
const QString kWait = QStringLiteral("wait");
const QString kSequence = QStringLiteral("sequence");
const QString kResume = QStringLiteral("resume");
constexpr int kStopFlushMs = 1000; // a quick stop after a timeout: time to reach the drive
constexpr int kFirstStatusRounds = 2; // status rounds read before a command starts

// Runs the event loop until done() or timeoutMs; keeps the deadman watchdog fed meanwhile
// (this process is alive and watching).
bool waitUntil(Axis &axis, const std::function<bool()> &done, int timeoutMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    while (!done()) {
        if (deadline.hasExpired())
            return false;
        axis.model->keepAlive();
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    }
    return true;
}

bool waitRounds(Axis &axis, int rounds, int timeoutMs)
{
    int seen = 0;
    const auto c =
        QObject::connect(axis.cia.get(), &AxisInterface::statusChanged, [&seen] { ++seen; });
    const bool ok = waitUntil(
        axis, [&] { return seen >= rounds; }, timeoutMs);
    QObject::disconnect(c);
    return ok;
}

RestoreSupervision::~RestoreSupervision()
{
    if (!supervision || !supervision->isArmed())
        return;
    if (auto restored = Reply::wait(supervision->disarm()); !restored)
        c.err << Tr::tr("drivebench-cli: warning: %1").arg(restored.error().message()) << Qt::endl;
}

// Arms the drive's own watch of this process where the connection offers one (CANopen node
// guarding or heartbeat with 6007h); null where none exists.
std::unique_ptr<canopen::DriveSupervision> superviseDrive(Context &c, Axis &axis)
{
    DeviceConnection *conn = axis.session.connection();
    if (canopen::DriveSupervision::modeFor(conn) == canopen::DriveSupervision::Mode::None)
        return nullptr;
    auto supervision = std::make_unique<canopen::DriveSupervision>(conn);
    if (auto armed = Reply::wait(supervision->arm()); !armed)
        c.err << Tr::tr("drivebench-cli: warning: %1").arg(armed.error().message()) << Qt::endl;
    else if (c.options.verbose)
        c.out << "supervision: " << supervision->description() << Qt::endl;
    return supervision;
}

Result<double> number(Context &c, const QString &option)
{
    bool ok = false;
    const double v = c.parser->value(option).toDouble(&ok);
    if (!ok)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("--%1 takes a number, not '%2'").arg(option, c.parser->value(option)));
    return v;
}

// The profile values given on the command line (--vel/--acc/--dec) replace what was read from
// the drive; options not given leave their field as it is.
Result<void> profileOptions(Context &c, MoveParams &p, bool withVelocity)
{
    for (const auto &[name, field] : { std::pair { kVel, &p.velocity },
                                       { kAcc, &p.acceleration },
                                       { kDec, &p.deceleration } }) {
        if (!c.parser->isSet(name) || (name == kVel && !withVelocity))
            continue;
        const auto v = number(c, name);
        if (!v)
            return v.error();
        *field = *v;
    }
    return {};
}

// Opens the connection, reads the scaling and the drive's limits and waits for the drive's
// status, so that the model knows whether it is enabled.
Result<std::unique_ptr<Axis>> openAxis(Context &c)
{
    auto axis = std::make_unique<Axis>(c);
    if (c.parser && c.parser->isSet(kWait)) {
        const auto w = number(c, kWait);
        if (!w || *w <= 0)
            return Error(Error::Kind::InvalidArgument, Tr::tr("--wait takes ms > 0"));
        axis->waitMs = int(*w);
    }
    if (auto opened = axis->session.open(c.args.at(0)); !opened)
        return opened.error();
    auto made = devices::makeAxis(axis->session.connection());
    if (!made)
        return made.error();
    axis->cia = std::move(made.value());
    if (auto init = Reply::wait(axis->cia->initialize()); !init)
        return init.error().prefixed(Tr::tr("reading the scaling"));
    axis->model = std::make_unique<MotionAxis>(axis->cia.get());
    axis->model->setConfig(axis->cia->limits());
    axis->model->setWatchdogTimeout(MotionAxis::kMaxWatchdogMs);
    if (!waitRounds(*axis, kFirstStatusRounds, c.options.requestTimeoutMs * 4))
        return Error(Error::Kind::Timeout, Tr::tr("no status from the drive"));
    return axis;
}

// Starts the command, waits for its end and reports it; 0 when it is Done.
int runToEnd(Context &c, Axis &axis, MotionCommand &command)
{
    command.setExecute(true);
    if (command.limits().notReferenced)
        c.err << Tr::tr("drivebench-cli: warning: the axis is not known to be referenced (no "
                        "homing seen, and the drive does not tell): positions count from the "
                        "drive's present zero")
              << Qt::endl;
    if (!waitUntil(
            axis, [&] { return command.isFinished(); }, axis.waitMs)) {
        axis.model->stopNow();
        waitUntil(
            axis, [&] { return !axis.cia->status().powered; }, kStopFlushMs);
        return fail(c,
                    Error(Error::Kind::Timeout,
                          Tr::tr("%1 not done within %2 ms (--wait); axis stopped")
                              .arg(command.name())
                              .arg(axis.waitMs)));
    }
    if (command.status() == MotionCommand::Status::Done)
        return ExitOk;
    if (command.refusal() != Refusal::None) {
        c.err << "drivebench-cli: " << command.error().message() << Qt::endl;
        return ExitDeviceError;
    }
    // The model has told the drive to stop (a lost heartbeat, a fault): that request must reach
    // the drive before the connection closes, so wait until the drive says it stands or is off.
    waitUntil(
        axis,
        [&] {
            const AxisInterface::Status s = axis.cia->status();
            return !s.powered || !s.moving;
        },
        kStopFlushMs);
    return fail(c, command.error());
}

void printPosition(Context &c, Axis &axis)
{
    waitRounds(axis, 1, c.options.requestTimeoutMs * 2); // a round read after the end
    const double p = axis.cia->status().position;
    if (c.options.verbose)
        c.out << "position: " << p << " (" << axisStateName(axis.model->state()) << ")" << Qt::endl;
    else
        c.out << p << Qt::endl;
}

// Runs the command to its end and prints where the axis stands then; 0 when it is Done.
int runAndReport(Context &c, Axis &axis, MotionCommand &command)
{
    if (const int rc = runToEnd(c, axis, command); rc != ExitOk)
        return rc;
    printPosition(c, axis);
    return ExitOk;
}

// The integer argument after the URI (a homing method, a motion block), then the axis: bad
// input is refused before the drive is touched. notANumber names the argument, %1 its text.
Result<std::unique_ptr<Axis>> openAxisFor(Context &c, int &number, const QString &notANumber)
{
    bool ok = false;
    number = c.args.at(1).toInt(&ok);
    if (!ok)
        return Error(Error::Kind::InvalidArgument, notANumber.arg(c.args.at(1)));
    return openAxis(c);
}

int power(Context &c, CommandKind kind, bool on)
{
    auto axis = openAxis(c);
    if (!axis)
        return fail(c, axis.error());
    MotionCommand command(axis.value()->model.get(), kind);
    command.setEnable(on);
    if (const int rc = runToEnd(c, *axis.value(), command); rc != ExitOk)
        return rc;
    c.out << axisStateName(axis.value()->model->state()) << Qt::endl;
    return ExitOk;
}

} // namespace motioncmd

using namespace motioncmd;

QList<QCommandLineOption> motionOptions()
{
    return {
        QCommandLineOption(kAbs, Tr::tr("move: absolute target (user units)."),
                           QStringLiteral("pos")),
        QCommandLineOption(kRel, Tr::tr("move: distance from the actual position."),
                           QStringLiteral("dist")),
        QCommandLineOption(kAdd, Tr::tr("move: distance from the last target (MC_MoveAdditive)."),
                           QStringLiteral("dist")),
        QCommandLineOption(kVel, Tr::tr("move, jog, velocity, home: velocity (units/s)."),
                           QStringLiteral("v")),
        QCommandLineOption(kAcc, Tr::tr("move, jog, home, gear: acceleration (units/s²)."),
                           QStringLiteral("a")),
        QCommandLineOption(
            kDec, Tr::tr("move, jog, velocity, halt, stop, gear: deceleration (units/s²)."),
            QStringLiteral("d")),
        QCommandLineOption(kTime, Tr::tr("jog, velocity, gear: how long to move (ms)."),
                           QStringLiteral("ms")),
        QCommandLineOption(kSequence, Tr::tr("travel: run the sequence that starts at BLOCK.")),
        QCommandLineOption(kResume, Tr::tr("travel: resume the interrupted block.")),
        QCommandLineOption(kWait,
                           Tr::tr("motion commands: longest wait for the end (ms, default "
                                  "60000)."),
                           QStringLiteral("ms")),
    };
}

int enable(Context &c)
{
    return power(c, CommandKind::Power, true);
}

int disable(Context &c)
{
    return power(c, CommandKind::Power, false);
}

int reset(Context &c)
{
    return power(c, CommandKind::Reset, true);
}

int home(Context &c)
{
    int method = 0;
    auto opened = openAxisFor(c, method, Tr::tr("METHOD is a homing method number, not '%1'"));
    if (!opened)
        return fail(c, opened.error());
    Axis &axis = *opened.value();
    HomingParams h = axis.cia->driveHoming();
    h.method = method;
    h.speedSlow = h.speedFast;
    for (const auto &[option, field] :
         { std::pair { kVel, &h.speedFast }, { kAcc, &h.acceleration } }) {
        if (!c.parser->isSet(option))
            continue;
        const auto v = number(c, option);
        if (!v)
            return fail(c, v.error());
        *field = *v;
    }
    h.speedSlow = h.speedFast;
    MotionCommand command(axis.model.get(), CommandKind::Home);
    command.setHoming(h);
    return runAndReport(c, axis, command);
}

int move(Context &c)
{
    CommandKind kind = CommandKind::DoNothing;
    QString option;
    int given = 0;
    for (const auto &[name, k] : { std::pair { kAbs, CommandKind::MoveAbsolute },
                                   { kRel, CommandKind::MoveRelative },
                                   { kAdd, CommandKind::MoveAdditive } }) {
        if (c.parser->isSet(name)) {
            kind = k;
            option = name;
            ++given;
        }
    }
    if (given != 1)
        return fail(c,
                    Error(Error::Kind::InvalidArgument,
                          Tr::tr("move takes exactly one of --abs, --rel, --add")));
    MoveParams p;
    if (const auto v = number(c, option); v)
        p.position = *v;
    else
        return fail(c, v.error());
    auto opened = openAxis(c);
    if (!opened)
        return fail(c, opened.error());
    Axis &axis = *opened.value();
    // The drive's own profile unless given.
    const AxisInterface::Profile own = axis.cia->driveProfile();
    p.velocity = own.velocity;
    p.acceleration = own.acceleration;
    p.deceleration = own.deceleration;
    p.jerk = axis.model->config().maxJerk;
    if (auto given = profileOptions(c, p, true); !given)
        return fail(c, given.error());
    MotionCommand command(axis.model.get(), kind);
    command.setParams(p);
    return runAndReport(c, axis, command);
}

namespace {
// --vel V (signed) and --time MS, checked.
Result<std::pair<double, double>> velocityAndTime(Context &c, const QString &command)
{
    if (!c.parser->isSet(kVel) || !c.parser->isSet(kTime))
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1 needs --vel V (signed) and --time MS").arg(command));
    const auto v = number(c, kVel);
    const auto t = number(c, kTime);
    if (!v || !t)
        return !v ? v.error() : t.error();
    if (*t <= 0 || *t > kDefaultWaitMs)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("--time takes 1..%1 ms").arg(kDefaultWaitMs));
    return std::pair { *v, *t };
}

// Moves at velocity v for t ms in leases renewed while this process runs (jog, and velocity on
// a drive with profile position): killed, frozen or cut off, it leaves a drive that brakes by
// itself at most LeasedMove::leaseTimeMs() after the last renewal. Then MC_Halt.
int runLeased(Context &c, Axis &axis, MoveParams p, double t)
{
    // Where the drive offers it (CANopen), the drive also watches this process while it moves.
    const auto supervision = superviseDrive(c, axis);
    const RestoreSupervision restore { supervision.get(), c };
    LeasedMove lease(axis.model.get());
    std::optional<MotionCommand::Status> ended;
    QObject::connect(&lease, &LeasedMove::ended, [&ended](MotionCommand::Status s) { ended = s; });
    lease.jog(p.velocity >= 0 ? 1 : -1, p);
    if (c.options.verbose)
        c.out << "lease: " << LeasedMove::kLeaseMs << " ms, " << lease.leaseTravel()
              << " units; the drive stops within " << qRound(lease.leaseTimeMs())
              << " ms if drivebench-cli stops" << Qt::endl;
    // For the time unless the move ends early (software limit, refused, fault, link lost, a
    // halt or stop from another process).
    const QDeadlineTimer until { qint64(t) };
    waitUntil(
        axis, [&] { return until.hasExpired() || ended.has_value(); }, int(t) + kStopFlushMs);
    const MotionCommand &moving = *lease.command();
    if (moving.status() == MotionCommand::Status::Error) {
        if (moving.refusal() != Refusal::None) {
            c.err << "drivebench-cli: " << moving.error().message() << Qt::endl;
            return ExitDeviceError;
        }
        return fail(c, moving.error());
    }
    if (!ended) {
        lease.halt();
        MotionCommand &halt = *lease.haltCommand();
        if (!waitUntil(
                axis, [&] { return halt.isFinished(); }, axis.waitMs)) {
            axis.model->stopNow();
            return fail(c,
                        Error(Error::Kind::Timeout,
                              Tr::tr("MC_Halt not done within %1 ms (--wait); axis "
                                     "stopped")
                                  .arg(axis.waitMs)));
        }
        if (halt.status() != MotionCommand::Status::Done)
            return fail(c, halt.error());
    }
    printPosition(c, axis);
    return ExitOk;
}
} // namespace

int jog(Context &c)
{
    const auto vt = velocityAndTime(c, QStringLiteral("jog"));
    if (!vt)
        return fail(c, vt.error());
    auto opened = openAxis(c);
    if (!opened)
        return fail(c, opened.error());
    Axis &axis = *opened.value();
    MoveParams p;
    p.velocity = vt->first;
    p.acceleration = p.deceleration = axis.cia->driveProfile().acceleration;
    if (auto given = profileOptions(c, p, false); !given)
        return fail(c, given.error());
    p.jerk = axis.model->config().maxJerk;
    return runLeased(c, axis, p, vt->second);
}

// Velocity V for --time ms, then MC_Halt: in leases like jog where the drive has profile
// position; otherwise MC_MoveVelocity, which the drive's velocity mode runs until told otherwise,
// so that only drive-side supervision stops it if this process dies.
int velocity(Context &c)
{
    const auto vt = velocityAndTime(c, QStringLiteral("velocity"));
    if (!vt)
        return fail(c, vt.error());
    auto opened = openAxis(c);
    if (!opened)
        return fail(c, opened.error());
    Axis &axis = *opened.value();
    MoveParams p;
    p.velocity = vt->first;
    p.acceleration = axis.cia->driveProfile().acceleration;
    p.deceleration = axis.cia->driveProfile().deceleration;
    if (auto given = profileOptions(c, p, false); !given)
        return fail(c, given.error());
    p.jerk = axis.model->config().maxJerk;
    if (axis.cia->features() & AxisInterface::Feature::ProfilePosition)
        return runLeased(c, axis, p, vt->second);
    // Velocity mode only (an ACTIVE Cube configured without positioning control): the drive's
    // velocity mode has no end point to lease, so only the drive's own supervision stops it.
    const auto supervision = superviseDrive(c, axis);
    const RestoreSupervision restore { supervision.get(), c };
    if (!supervision && axis.cia->linkSupervision().isEmpty())
        c.err << Tr::tr("drivebench-cli: warning: the drive has no profile position mode, so "
                        "MC_MoveVelocity cannot move in leases, and nothing on the drive's side "
                        "stops it if drivebench-cli dies on this connection")
              << Qt::endl;
    else if (!supervision && c.options.verbose)
        c.out << "supervision: " << axis.cia->linkSupervision() << Qt::endl;
    MotionCommand command(axis.model.get(), CommandKind::MoveVelocity);
    command.setParams(p);
    command.setExecute(true);
    const QDeadlineTimer until { qint64(vt->second) };
    waitUntil(
        axis,
        [&] {
            return until.hasExpired() || command.status() == MotionCommand::Status::Error
                || command.status() == MotionCommand::Status::CommandAborted;
        },
        int(vt->second) + kStopFlushMs);
    if (command.status() == MotionCommand::Status::Error) {
        if (command.refusal() != Refusal::None) {
            c.err << "drivebench-cli: " << command.error().message() << Qt::endl;
            return ExitDeviceError;
        }
        return fail(c, command.error());
    }
    MotionCommand halt(axis.model.get(), CommandKind::Halt);
    halt.setParams(p);
    return runAndReport(c, axis, halt);
}

namespace {
// MC_Halt / MC_Stop of whatever moves the drive (this or another tool): brakes with --dec or the
// drive's 6084h and waits for standstill.
int brake(Context &c, CommandKind kind)
{
    auto opened = openAxis(c);
    if (!opened)
        return fail(c, opened.error());
    Axis &axis = *opened.value();
    MoveParams p;
    p.deceleration = axis.cia->driveProfile().deceleration;
    if (c.parser->isSet(kDec)) {
        const auto d = number(c, kDec);
        if (!d)
            return fail(c, d.error());
        p.deceleration = *d;
    }
    p.jerk = axis.model->config().maxJerk;
    MotionCommand command(axis.model.get(), kind);
    command.setParams(p);
    return runAndReport(c, axis, command);
}
} // namespace

int halt(Context &c)
{
    return brake(c, CommandKind::Halt);
}

int stop(Context &c)
{
    return brake(c, CommandKind::Stop);
}

int travel(Context &c)
{
    int block = 0;
    auto opened = openAxisFor(c, block, Tr::tr("BLOCK is a motion block number, not '%1'"));
    if (!opened)
        return fail(c, opened.error());
    Axis &axis = *opened.value();
    MoveParams p;
    p.block = block;
    p.sequence = c.parser->isSet(kSequence);
    p.resume = c.parser->isSet(kResume);
    MotionCommand command(axis.model.get(), CommandKind::MotionBlock);
    command.setParams(p);
    return runAndReport(c, axis, command);
}

} // namespace db::cli
