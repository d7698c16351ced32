#include "simconsole.h"

#include "demodrive.h"
#include "devices/movingcap/movingcapdrive.h"

namespace db::app {

namespace {
constexpr int kStandstillPollMs = 2; // finer than the drive's 5 ms real-time step

QString hex4(quint16 value)
{
    return QString::number(value, 16).toUpper().rightJustified(4, QLatin1Char('0'));
}
} // namespace

SimConsole::SimConsole(DemoDrive *demo, QObject *parent)
    : QObject(parent)
    , m_demo(demo)
{
    m_standstill.setInterval(kStandstillPollMs);
    m_standstill.setTimerType(Qt::PreciseTimer);
    connect(&m_standstill, &QTimer::timeout, this, &SimConsole::checkStandstill);
}

Result<quint16> SimConsole::parseFaultCode(const QString &text)
{
    QString hex = text.trimmed();
    if (hex.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        hex = hex.mid(2);
    else if (hex.endsWith(QLatin1Char('h'), Qt::CaseInsensitive))
        hex.chop(1);
    bool ok = false;
    const uint code = hex.toUInt(&ok, 16);
    if (!ok || code == 0 || code > 0xFFFF)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("a fault is a hexadecimal EMCY code 1..FFFF (e.g. 7121), not "
                                    "'%1'")
                         .arg(text));
    return quint16(code);
}

QString SimConsole::motion() const
{
    const sim::MovingCapDrive &drive = m_demo->drive();
    return QStringLiteral("%1 position %2 velocity %3")
        .arg(qRound64(drive.time() * 1000))
        .arg(drive.axis().position(), 0, 'f', 1)
        .arg(drive.axis().velocity(), 0, 'f', 1);
}

void SimConsole::execute(const QString &line)
{
    const QStringList words = line.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    const QString command = words.value(0);
    if (command == u"state" && words.size() == 1) {
        Q_EMIT answered(QStringLiteral("state %1 statusword 0x%2")
                            .arg(motion())
                            .arg(hex4(m_demo->drive().statusword())));
    } else if (command == u"standstill" && words.size() == 1) {
        ++m_standstillOwed;
        checkStandstill();
        if (m_standstillOwed > 0)
            m_standstill.start();
    } else if (command == u"drop" && words.size() == 1) {
        const QString before = motion(); // the moment of the cut, before anything reacts
        Q_EMIT answered(QStringLiteral("dropped %1 %2").arg(m_demo->dropClients()).arg(before));
    } else if (command == u"fault" && words.size() == 2) {
        const auto code = parseFaultCode(words.at(1));
        if (!code) {
            Q_EMIT answered(QStringLiteral("error: ") + code.error().message());
            return;
        }
        m_demo->drive().injectFault(*code);
        Q_EMIT answered(QStringLiteral("fault ") + hex4(*code));
    } else if (command == u"heartbeat" && words.size() == 2
               && (words.at(1) == u"off" || words.at(1) == u"on")) {
        m_demo->setHeartbeatSilenced(words.at(1) == u"off");
        Q_EMIT answered(QStringLiteral("heartbeat ") + words.at(1));
    } else if (!command.isEmpty()) {
        Q_EMIT answered(QStringLiteral("error: unknown command '%1' (state, standstill, drop, "
                                       "fault CODE, heartbeat off|on)")
                            .arg(line.simplified()));
    }
}

void SimConsole::checkStandstill()
{
    if (m_standstillOwed == 0 || m_demo->drive().axis().isMoving())
        return;
    const QString at = motion();
    for (; m_standstillOwed > 0; --m_standstillOwed)
        Q_EMIT answered(QStringLiteral("standstill ")
                        + at.section(QLatin1String(" velocity"), 0, 0));
    m_standstill.stop();
}

} // namespace db::app
