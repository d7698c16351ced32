#include "motionchangelog.h"

#include "motionaxis.h"
#include "motioncommand.h"

#include "core/changelog.h"

#include <QHash>
#include <QPointer>

namespace db::motion {

namespace {

QString number(double v)
{
    return QString::number(v, 'g', 10);
}

QString inputs(const MotionCommand &c)
{
    const MoveParams &p = c.latched();
    switch (c.kind()) {
    case CommandKind::MoveAbsolute:
        return QCoreApplication::translate("MotionChangeLog", "target %1 at %2")
            .arg(number(p.position), number(p.velocity));
    case CommandKind::MoveRelative:
    case CommandKind::MoveAdditive:
        return QCoreApplication::translate("MotionChangeLog", "distance %1 at %2")
            .arg(number(p.position), number(p.velocity));
    case CommandKind::MoveVelocity:
        return QCoreApplication::translate("MotionChangeLog", "velocity %1")
            .arg(number(p.velocity));
    case CommandKind::Home:
        return QCoreApplication::translate("MotionChangeLog", "method %1").arg(c.homing().method);
    case CommandKind::MotionBlock:
        return QCoreApplication::translate("MotionChangeLog", "block %1").arg(p.block);
    case CommandKind::GearIn:
        return QCoreApplication::translate("MotionChangeLog", "ratio %1:%2")
            .arg(p.gearNumerator)
            .arg(p.gearDenominator);
    case CommandKind::TorqueControl:
        return QCoreApplication::translate("MotionChangeLog", "torque %1").arg(number(p.torque));
    default:
        return {};
    }
}

// Lives as the axis's child: gone with the axis.
class Recorder : public QObject
{
public:
    Recorder(MotionAxis *axis, ChangeLog *log, const QString &device)
        : QObject(axis)
        , m_log(log)
        , m_device(device)
    {
        connect(axis, &MotionAxis::commandStarted, this, &Recorder::onStarted);
    }

private:
    void onStarted(MotionCommand *command)
    {
        if (!m_log)
            return;
        const auto known = m_entries.constFind(command);
        if (known != m_entries.cend()) {
            const ChangeLog::Entry *e = m_log->find(*known);
            const bool motion =
                command->kind() != CommandKind::Power && command->kind() != CommandKind::Reset;
            if (e && e->outcome == ChangeLog::Outcome::Pending && command->isBusy() && motion)
                return; // restarted while running: the same action goes on
            m_log->complete(*known, {}); // enable/disable and reset: each start is its own
        }
        ChangeLog::Entry e;
        e.device = m_device;
        e.object = command->name();
        switch (command->kind()) {
        case CommandKind::Power:
            e.kind = command->latchedEnable() ? ChangeLog::Kind::Enable : ChangeLog::Kind::Disable;
            break;
        case CommandKind::Reset:
            e.kind = ChangeLog::Kind::Reset;
            break;
        default:
            e.kind = ChangeLog::Kind::Motion;
            e.newValue = inputs(*command);
            break;
        }
        const bool firstTime = !m_entries.contains(command);
        m_entries.insert(command, m_log->add(e));
        if (firstTime) {
            connect(command, &MotionCommand::statusChanged, this,
                    [this, command](MotionCommand::Status s) { onStatus(command, s); });
            connect(command, &QObject::destroyed, this, [this, command] {
                if (m_log) {
                    const int id = m_entries.value(command);
                    m_log->complete(
                        id,
                        Error(Error::Kind::Cancelled,
                              QCoreApplication::translate("MotionChangeLog", "command removed")));
                }
                m_entries.remove(command);
            });
        }
        // commandStarted comes before the axis starts the command: its status is still the one
        // of its previous run (Done, Error), which says nothing about this one. Even a refusal
        // arrives later, through statusChanged.
    }

    void onStatus(MotionCommand *command, MotionCommand::Status s)
    {
        if (!m_log || !m_entries.contains(command))
            return;
        const int id = m_entries.value(command);
        switch (s) {
        case MotionCommand::Status::Done:
            m_log->complete(id, {});
            break;
        case MotionCommand::Status::CommandAborted:
            m_log->complete(
                id, ChangeLog::Outcome::Aborted,
                command->error().isError()
                    ? command->error().toString()
                    : QCoreApplication::translate("MotionChangeLog", "ended by another command"));
            break;
        case MotionCommand::Status::Error:
            m_log->complete(id,
                            command->error().isError()
                                ? command->error()
                                : Error(Error::Kind::DeviceError,
                                        QCoreApplication::translate("MotionChangeLog", "failed")));
            break;
        default:
            break;
        }
    }

    QPointer<ChangeLog> m_log;
    QString m_device;
    QHash<MotionCommand *, int> m_entries;
};

} // namespace

void recordCommands(MotionAxis *axis, ChangeLog *log, const QString &device)
{
    if (axis && log)
        new Recorder(axis, log, device);
}

} // namespace db::motion
