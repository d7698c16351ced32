#include "acuconsole.h"

#include "devices/bonfiglioli/simulatedacu.h"

#include <cmath>

namespace db::app {

AcuConsole::AcuConsole(bonfiglioli::SimulatedAcu *acu, QObject *parent)
    : DeviceConsole(parent)
    , m_acu(acu)
{
    m_clock.start();
}

Result<quint16> AcuConsole::parseFaultCode(const QString &text)
{
    QString hex = text.trimmed();
    if (hex.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        hex = hex.mid(2);
    else if (hex.startsWith(QLatin1Char('F'), Qt::CaseInsensitive))
        hex = hex.mid(1);
    bool ok = false;
    const uint code = hex.toUInt(&ok, 16);
    if (!ok || code == 0 || code > 0xFFFF)
        return Error(Error::Kind::InvalidArgument,
                     QStringLiteral("a fault is a code 1..FFFF in hex as parameter 260 shows it "
                                    "(e.g. 2714 for F2714), not '%1'")
                         .arg(text));
    return quint16(code);
}

QString AcuConsole::motion() const
{
    return QStringLiteral("%1 position %2 velocity %3")
        .arg(m_clock.elapsed())
        .arg(m_acu->motion().position(), 0, 'f', 1)
        .arg(m_acu->motion().velocity(), 0, 'f', 1);
}

bool AcuConsole::isMoving() const
{
    return m_acu->motion().velocity() != 0.0;
}

QString AcuConsole::stateDetails() const
{
    return QStringLiteral(" statusword 0x%1 mode %2 fault 0x%3")
        .arg(hex4(m_acu->statusWord()))
        .arg(m_acu->motion().mode())
        .arg(hex4(m_acu->fault()));
}

int AcuConsole::dropClients()
{
    return m_acu->dropClient();
}

void AcuConsole::injectFault(quint16 code)
{
    m_acu->raiseFault(code);
}

bool AcuConsole::executeOwn(const QStringList &words)
{
    if (words.size() != 2)
        return false;
    const QString &command = words.at(0);
    const QString &argument = words.at(1);
    const bool onOff = argument == u"on" || argument == u"off";
    if (command == u"mains" && onOff) {
        m_acu->motion().setMains(argument == u"on");
    } else if (command == u"sto" && onOff) {
        m_acu->motion().setSto(argument == u"on");
    } else if (command == u"master") {
        bool ok = false;
        const double speed = argument.toDouble(&ok);
        if (!ok || !std::isfinite(speed)) {
            Q_EMIT answered(
                QStringLiteral("error: master takes a speed in u/s, not '%1'").arg(argument));
            return true;
        }
        m_acu->motion().setMasterSpeed(speed);
        Q_EMIT answered(QStringLiteral("master ") + QString::number(speed));
        return true;
    } else if (command == u"watchdog") {
        bool ok = false;
        const int ms = argument.toInt(&ok);
        if (!ok || ms < 1 || ms > 3600000) {
            Q_EMIT answered(QStringLiteral("error: watchdog takes a time in ms (1..3600000), not "
                                           "'%1'")
                                .arg(argument));
            return true;
        }
        m_acu->setWatchdogMs(ms);
        Q_EMIT answered(QStringLiteral("watchdog ") + QString::number(ms));
        return true;
    } else {
        return false;
    }
    Q_EMIT answered(command + u' ' + argument);
    return true;
}

} // namespace db::app
