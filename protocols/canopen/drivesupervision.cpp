#include "drivesupervision.h"

#include "cannetwork.h"
#include "heartbeatproducer.h"
#include "nodeguarding.h"

#include <QCoreApplication>
#include <memory>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

namespace {
const ObjectAddress kGuardTimeObject(0x100C, 0);
const ObjectAddress kLifeTimeFactorObject(0x100D, 0);
const ObjectAddress kConsumerHeartbeatObject(0x1016, 1);
const ObjectAddress kAbortConnectionObject(0x6007, 0);
} // namespace

DriveSupervision::DriveSupervision(DeviceConnection *connection, QObject *parent)
    : QObject(parent)
    , m_connection(connection)
    , m_mode(modeFor(connection))
{
    const NetworkNode at = networkNodeOf(connection);
    m_network = at.network;
    m_node = at.node;
}

DriveSupervision::~DriveSupervision()
{
    stopOurSide();
}

DriveSupervision::Mode DriveSupervision::modeFor(const DeviceConnection *connection)
{
    if (!networkNodeOf(connection))
        return Mode::None;
    const ObjectDictionary &dict = connection->dictionary();
    if (dict.contains(kConsumerHeartbeatObject))
        return Mode::Heartbeat;
    if (dict.contains(kGuardTimeObject) && dict.contains(kLifeTimeFactorObject))
        return Mode::Guarding;
    return Mode::None;
}

bool DriveSupervision::hasAbortOption() const
{
    return m_connection && m_connection->dictionary().contains(kAbortConnectionObject);
}

QString DriveSupervision::description() const
{
    const QString reaction = hasAbortOption() ? Tr::tr("6007h = 3, quick stop")
                                              : Tr::tr("no 6007h: the drive's own reaction");
    switch (mode()) {
    case Mode::Heartbeat:
        return Tr::tr("drive stops within %1 ms if drivebench stops (our heartbeat from "
                      "node %2 every %3 ms, watched by the drive's 1016h; %4)")
            .arg(kReactionMs)
            .arg(m_network ? m_network->heartbeat()->nodeId() : 0)
            .arg(kPeriodMs)
            .arg(reaction);
    case Mode::Guarding:
        return Tr::tr("drive stops within %1 ms if drivebench stops (node guarding every "
                      "%2 ms, life time %1 ms; %3)")
            .arg(kReactionMs)
            .arg(kPeriodMs)
            .arg(reaction);
    case Mode::None:
        break;
    }
    return m_network ? Tr::tr("no drive-side supervision: node %1 describes neither 1016h "
                              "nor 100Ch/100Dh; only the motion lease bounds a jog")
                           .arg(m_node)
                     : Tr::tr("no drive-side supervision on this connection; only the motion "
                              "lease bounds a jog");
}

Reply *DriveSupervision::arm()
{
    const Mode m = mode();
    if (m == Mode::None || !m_network)
        return Reply::failed({}, Error(Error::Kind::NotSupported, description()));
    if (m_armed) {
        auto *done = new Reply();
        done->finish();
        return done;
    }
    DeviceConnection *c = m_connection;
    // Reads the drive's own value into `previous`, once: an arm() repeated before disarm()
    // finished would otherwise read back our own settings.
    auto remember = [c](ObjectAddress a, QVariant *previous) {
        return Step { [c, a] { return c->read(a); },
                      [previous](const QVariant &v) {
                          if (!previous->isValid())
                              *previous = v;
                      } };
    };
    auto set = [c](ObjectAddress a, QVariant v) {
        return Step { [c, a, v] { return c->write(a, v); }, {} };
    };
    QList<Step> steps;
    if (hasAbortOption())
        steps << remember(kAbortConnectionObject, &m_previousAbort)
              << set(kAbortConnectionObject, kAbortQuickStop);
    if (m == Mode::Heartbeat) {
        const quint32 entry =
            quint32(m_network->heartbeat()->nodeId()) << 16 | quint32(kReactionMs);
        steps << remember(kConsumerHeartbeatObject, &m_previousConsumer)
              << set(kConsumerHeartbeatObject, QVariant::fromValue<qulonglong>(entry));
    } else {
        steps << remember(kGuardTimeObject, &m_previousGuardTime)
              << remember(kLifeTimeFactorObject, &m_previousLifeFactor)
              << set(kGuardTimeObject, kPeriodMs) << set(kLifeTimeFactorObject, kLifeTimeFactor);
    }
    steps << Step { [this]() -> Reply * {
                       startOurSide();
                       m_armed = true;
                       return nullptr;
                   },
                    {} };
    return run(steps, Tr::tr("setting up drive-side supervision"));
}

Reply *DriveSupervision::disarm()
{
    if (!m_armed) {
        auto *done = new Reply();
        done->finish();
        return done;
    }
    m_armed = false;
    DeviceConnection *c = m_connection;
    auto write = [c](ObjectAddress a, QVariant v) {
        return Step { [c, a, v]() -> Reply * { return v.isValid() ? c->write(a, v) : nullptr; },
                      {} };
    };
    QList<Step> steps;
    if (mode() == Mode::Heartbeat)
        steps << write(kConsumerHeartbeatObject, m_previousConsumer);
    else
        steps << write(kLifeTimeFactorObject, m_previousLifeFactor)
              << write(kGuardTimeObject, m_previousGuardTime);
    steps << Step { [this] {
                       stopOurSide();
                       return nullptr;
                   },
                    {} };
    if (hasAbortOption())
        steps << write(kAbortConnectionObject, m_previousAbort);
    Reply *result = run(steps, Tr::tr("restoring the drive's supervision settings"));
    // Whatever happens to the writes, our side stops: the drive then reacts, which is safe.
    connect(result, &Reply::finished, this, [this, result] {
        stopOurSide();
        if (result->ok() && !m_armed) // restored: the next arm() reads the drive's values anew
            m_previousAbort = m_previousConsumer = m_previousGuardTime = m_previousLifeFactor = {};
    });
    return result;
}

Reply *DriveSupervision::run(const QList<Step> &steps, const QString &what)
{
    auto *result = new Reply();
    runFrom(std::make_shared<Run>(Run { steps, result, what }), 0);
    return result;
}

void DriveSupervision::runFrom(const std::shared_ptr<Run> &run, int step)
{
    if (!run->result)
        return; // the caller lost interest
    for (int i = step; i < run->steps.size(); ++i) {
        if (!m_connection) {
            run->result->fail(Error(Error::Kind::Disconnected,
                                    run->what + QStringLiteral(": the connection is gone")));
            return;
        }
        Reply *r = run->steps.at(i).start();
        if (!r)
            continue;
        connect(r, &Reply::finished, this, [this, r, run, i] {
            r->deleteLater();
            if (!run->result)
                return;
            if (!r->ok()) {
                run->result->fail(r->error().prefixed(run->what));
                return;
            }
            if (run->steps.at(i).done)
                run->steps.at(i).done(r->value());
            runFrom(run, i + 1);
        });
        return;
    }
    run->result->finish();
}

void DriveSupervision::startOurSide()
{
    if (!m_network || m_ourSideRunning)
        return;
    m_ourSideRunning = true;
    if (m_mode == Mode::Heartbeat)
        m_network->heartbeat()->acquire(kPeriodMs);
    else
        m_network->guarding()->guard(m_node, kPeriodMs);
}

void DriveSupervision::stopOurSide()
{
    if (!m_ourSideRunning)
        return;
    m_ourSideRunning = false;
    if (!m_network)
        return;
    if (m_mode == Mode::Heartbeat)
        m_network->heartbeat()->release();
    else
        m_network->guarding()->unguard(m_node);
}

} // namespace db::canopen
