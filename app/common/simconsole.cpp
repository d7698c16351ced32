#include "simconsole.h"

#include "demodrive.h"
#include "devices/movingcap/movingcapdrive.h"

namespace db::app {

SimConsole::SimConsole(DemoDrive *demo, QObject *parent)
    : DeviceConsole(parent)
    , m_demo(demo)
{ }

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

bool SimConsole::isMoving() const
{
    return m_demo->drive().axis().isMoving();
}

QString SimConsole::stateDetails() const
{
    return QStringLiteral(" statusword 0x") + hex4(m_demo->drive().statusword());
}

int SimConsole::dropClients()
{
    return m_demo->dropClients();
}

void SimConsole::injectFault(quint16 code)
{
    m_demo->drive().injectFault(code);
}

bool SimConsole::executeOwn(const QStringList &words)
{
    if (words.size() != 2 || words.at(0) != u"heartbeat"
        || (words.at(1) != u"off" && words.at(1) != u"on"))
        return false;
    m_demo->setHeartbeatSilenced(words.at(1) == u"off");
    Q_EMIT answered(QStringLiteral("heartbeat ") + words.at(1));
    return true;
}

} // namespace db::app
