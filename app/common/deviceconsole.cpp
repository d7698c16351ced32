#include "deviceconsole.h"

namespace db::app {

namespace {
constexpr int kStandstillPollMs = 2; // finer than the simulated drives' 5 ms step
} // namespace

DeviceConsole::DeviceConsole(QObject *parent)
    : QObject(parent)
{
    m_standstill.setInterval(kStandstillPollMs);
    m_standstill.setTimerType(Qt::PreciseTimer);
    connect(&m_standstill, &QTimer::timeout, this, &DeviceConsole::checkStandstill);
}

QString DeviceConsole::hex4(quint16 value)
{
    return QString::number(value, 16).toUpper().rightJustified(4, QLatin1Char('0'));
}

void DeviceConsole::execute(const QString &line)
{
    const QStringList words = line.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    const QString command = words.value(0);
    if (command == u"state" && words.size() == 1) {
        Q_EMIT answered(QStringLiteral("state ") + motion() + stateDetails());
    } else if (command == u"standstill" && words.size() == 1) {
        ++m_standstillOwed;
        checkStandstill();
        if (m_standstillOwed > 0)
            m_standstill.start();
    } else if (command == u"drop" && words.size() == 1) {
        const QString before = motion(); // the moment of the cut, before anything reacts
        Q_EMIT answered(QStringLiteral("dropped %1 %2").arg(dropClients()).arg(before));
    } else if (command == u"fault" && words.size() == 2) {
        const auto code = parseFault(words.at(1));
        if (!code) {
            Q_EMIT answered(QStringLiteral("error: ") + code.error().message());
            return;
        }
        injectFault(*code);
        Q_EMIT answered(QStringLiteral("fault ") + hex4(*code));
    } else if (!command.isEmpty() && !executeOwn(words)) {
        Q_EMIT answered(
            QStringLiteral("error: unknown command '%1' (state, standstill, drop, fault CODE, %2)")
                .arg(line.simplified(), ownCommands()));
    }
}

void DeviceConsole::checkStandstill()
{
    if (m_standstillOwed == 0 || isMoving())
        return;
    const QString at = motion();
    for (; m_standstillOwed > 0; --m_standstillOwed)
        Q_EMIT answered(QStringLiteral("standstill ")
                        + at.section(QLatin1String(" velocity"), 0, 0));
    m_standstill.stop();
}

} // namespace db::app
