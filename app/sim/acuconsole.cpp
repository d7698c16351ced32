#include "acuconsole.h"

#include "devices/bonfiglioli/simulatedacu.h"

#include <cmath>

namespace db::app {

namespace {
constexpr int kStandstillPollMs = 2; // finer than the motion model's 5 ms step

QString hex4(quint16 value)
{
    return QString::number(value, 16).toUpper().rightJustified(4, QLatin1Char('0'));
}
} // namespace

AcuConsole::AcuConsole(bonfiglioli::SimulatedAcu *acu, QObject *parent)
    : QObject(parent)
    , m_acu(acu)
{
    m_clock.start();
    m_standstill.setInterval(kStandstillPollMs);
    m_standstill.setTimerType(Qt::PreciseTimer);
    connect(&m_standstill, &QTimer::timeout, this, &AcuConsole::checkStandstill);
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

void AcuConsole::execute(const QString &line)
{
    const QStringList words = line.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    const QString command = words.value(0);
    const bool onOff = words.size() == 2 && (words.at(1) == u"on" || words.at(1) == u"off");
    if (command == u"state" && words.size() == 1) {
        Q_EMIT answered(QStringLiteral("state %1 statusword 0x%2 mode %3 fault 0x%4")
                            .arg(motion())
                            .arg(hex4(m_acu->statusWord()))
                            .arg(m_acu->motion().mode())
                            .arg(hex4(m_acu->fault())));
    } else if (command == u"standstill" && words.size() == 1) {
        ++m_standstillOwed;
        checkStandstill();
        if (m_standstillOwed > 0)
            m_standstill.start();
    } else if (command == u"drop" && words.size() == 1) {
        const QString before = motion(); // the moment of the cut, before anything reacts
        Q_EMIT answered(QStringLiteral("dropped %1 %2").arg(m_acu->dropClient()).arg(before));
    } else if (command == u"fault" && words.size() == 2) {
        const auto code = parseFaultCode(words.at(1));
        if (!code) {
            Q_EMIT answered(QStringLiteral("error: ") + code.error().message());
            return;
        }
        m_acu->raiseFault(*code);
        Q_EMIT answered(QStringLiteral("fault ") + hex4(*code));
    } else if (command == u"mains" && onOff) {
        m_acu->motion().setMains(words.at(1) == u"on");
        Q_EMIT answered(QStringLiteral("mains ") + words.at(1));
    } else if (command == u"sto" && onOff) {
        m_acu->motion().setSto(words.at(1) == u"on");
        Q_EMIT answered(QStringLiteral("sto ") + words.at(1));
    } else if (command == u"master" && words.size() == 2) {
        bool ok = false;
        const double speed = words.at(1).toDouble(&ok);
        if (!ok || !std::isfinite(speed)) {
            Q_EMIT answered(
                QStringLiteral("error: master takes a speed in u/s, not '%1'").arg(words.at(1)));
            return;
        }
        m_acu->motion().setMasterSpeed(speed);
        Q_EMIT answered(QStringLiteral("master ") + QString::number(speed));
    } else if (command == u"watchdog" && words.size() == 2) {
        bool ok = false;
        const int ms = words.at(1).toInt(&ok);
        if (!ok || ms < 1 || ms > 3600000) {
            Q_EMIT answered(QStringLiteral("error: watchdog takes a time in ms (1..3600000), not "
                                           "'%1'")
                                .arg(words.at(1)));
            return;
        }
        m_acu->setWatchdogMs(ms);
        Q_EMIT answered(QStringLiteral("watchdog ") + QString::number(ms));
    } else if (!command.isEmpty()) {
        Q_EMIT answered(
            QStringLiteral("error: unknown command '%1' (state, standstill, drop, "
                           "fault CODE, mains on|off, sto on|off, master SPEED, watchdog MS)")
                .arg(line.simplified()));
    }
}

void AcuConsole::checkStandstill()
{
    if (m_standstillOwed == 0 || m_acu->motion().velocity() != 0.0)
        return;
    const QString at = motion();
    for (; m_standstillOwed > 0; --m_standstillOwed)
        Q_EMIT answered(QStringLiteral("standstill ")
                        + at.section(QLatin1String(" velocity"), 0, 0));
    m_standstill.stop();
}

} // namespace db::app
