#include "drivecontroller.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::cia402)
};
} // namespace

namespace db::cia402 {

namespace {
bool isOff(State s)
{
    return s == State::SwitchOnDisabled || s == State::Fault;
}

Sequence::Check stateIs(QList<State> wanted)
{
    return [wanted](quint16 word, QString &why) {
        const State s = decodeState(word);
        if (wanted.contains(s))
            return WaitVerdict::Reached;
        if (s == State::Fault || s == State::FaultReactionActive) {
            why = Tr::tr("the drive went to fault");
            return WaitVerdict::Failed;
        }
        return WaitVerdict::Pending;
    };
}
} // namespace

DriveController::DriveController(DeviceConnection *connection, QObject *parent)
    : QObject(parent)
    , m_connection(connection)
{ }

QList<DriveController::Step> DriveController::plan(State from, State to)
{
    using S = State;
    if (from == to)
        return {};
    switch (from) {
    case S::Fault:
        // Fault reset acts on the 0->1 edge of bit 7 (movingcap.md 5.1).
        return QList<Step> { { cw::DisableVoltage, S::Fault },
                             { cw::FaultResetCmd, S::SwitchOnDisabled } }
        + plan(S::SwitchOnDisabled, to);
    case S::QuickStopActive:
        return QList<Step> { { cw::DisableVoltage, S::SwitchOnDisabled } }
        + plan(S::SwitchOnDisabled, to);
    case S::SwitchOnDisabled:
        if (to == S::Fault)
            return {};
        return QList<Step> { { cw::Shutdown, S::ReadyToSwitchOn } } + plan(S::ReadyToSwitchOn, to);
    case S::ReadyToSwitchOn:
        if (to == S::SwitchOnDisabled)
            return { { cw::DisableVoltage, S::SwitchOnDisabled } };
        return QList<Step> { { cw::SwitchOnCmd, S::SwitchedOn } } + plan(S::SwitchedOn, to);
    case S::SwitchedOn:
        if (to == S::OperationEnabled)
            return { { cw::EnableOperationCmd, S::OperationEnabled } };
        if (to == S::ReadyToSwitchOn)
            return { { cw::Shutdown, S::ReadyToSwitchOn } };
        return { { cw::DisableVoltage, S::SwitchOnDisabled } };
    case S::OperationEnabled:
        if (to == S::SwitchedOn)
            return { { cw::DisableOperation, S::SwitchedOn } };
        if (to == S::ReadyToSwitchOn)
            return { { cw::Shutdown, S::ReadyToSwitchOn } };
        return { { cw::DisableVoltage, S::SwitchOnDisabled } };
    case S::NotReadyToSwitchOn:
    case S::FaultReactionActive:
    case S::Unknown:
        break;
    }
    return {};
}

Reply *DriveController::run(Sequence *sequence)
{
    if (m_running)
        m_running->cancel(
            Error(Error::Kind::Cancelled,
                  m_running->name() + QStringLiteral(": superseded by ") + sequence->name()));
    m_running = sequence;
    return sequence->start();
}

Reply *DriveController::goTo(State target, const QString &name)
{
    auto *seq = new Sequence(m_connection, name, this);
    seq->waitFor(Tr::tr("reading the state"),
                 [](quint16, QString &) { return WaitVerdict::Reached; });
    seq->call([target](Sequence *s) {
        const State from = decodeState(s->lastStatusword());
        if (from == target || (target == State::SwitchOnDisabled && isOff(from)))
            return;
        const QList<Step> steps = plan(from, target);
        if (steps.isEmpty()) {
            s->waitFor(Tr::tr("a state from which %1 can be reached").arg(stateName(target)),
                       [](quint16, QString &why) {
                           why = Tr::tr("no transition from this state");
                           return WaitVerdict::Failed;
                       });
            return;
        }
        for (const Step &step : steps) {
            s->controlword(step.controlword);
            s->waitFor(stateName(step.expected), stateIs({ step.expected }), kStepTimeoutMs);
        }
    });
    return run(seq);
}

Reply *DriveController::shutdown()
{
    return goTo(State::ReadyToSwitchOn, QStringLiteral("shutdown"));
}

Reply *DriveController::switchOn()
{
    return goTo(State::SwitchedOn, Tr::tr("switch on"));
}

Reply *DriveController::enableOperation()
{
    return goTo(State::OperationEnabled, Tr::tr("enable operation"));
}

Reply *DriveController::disableVoltage()
{
    return goTo(State::SwitchOnDisabled, Tr::tr("disable voltage"));
}

Reply *DriveController::faultReset()
{
    auto *seq = new Sequence(m_connection, Tr::tr("fault reset"), this);
    seq->waitFor(Tr::tr("reading the state"),
                 [](quint16, QString &) { return WaitVerdict::Reached; });
    seq->call([](Sequence *s) {
        const State from = decodeState(s->lastStatusword());
        if (from == State::FaultReactionActive)
            s->waitFor(stateName(State::Fault), stateIs({ State::Fault }), kStepTimeoutMs);
        else if (from != State::Fault)
            return;
        s->controlword(cw::DisableVoltage);
        s->controlword(cw::FaultResetCmd);
        s->waitFor(stateName(State::SwitchOnDisabled), stateIs({ State::SwitchOnDisabled }),
                   kStepTimeoutMs);
    });
    return run(seq);
}

Reply *DriveController::quickStop()
{
    auto *seq = new Sequence(m_connection, Tr::tr("quick stop"), this);
    // Written at once, without reading first: a stop must not wait for a round trip.
    seq->controlword(cw::QuickStopCmd | cw::SwitchOn | cw::EnableOperation);
    seq->waitFor(
        Tr::tr("quick stop active or switch on disabled"),
        [](quint16 word, QString &) {
            const State s = decodeState(word);
            return s == State::OperationEnabled ? WaitVerdict::Pending : WaitVerdict::Reached;
        },
        kQuickStopTimeoutMs);
    return run(seq);
}

} // namespace db::cia402
