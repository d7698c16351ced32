#include "framesender.h"

#include "core/changelog.h"
#include "transport/canbus.h"
#include "widgets/common/flowlayout.h"
#include "widgets/common/widgetstyle.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace db::widgets {

namespace {

constexpr quint32 kMaxStandardId = 0x7FF;
constexpr quint32 kMaxExtendedId = 0x1FFFFFFF;

Error invalid(const QString &text)
{
    return Error(Error::Kind::InvalidArgument, text);
}

// "601 40 00 10 00": the identifier and the data bytes as typed in the sender (hex).
QString frameText(const QCanBusFrame &frame)
{
    QString text = QString::number(frame.frameId(), 16).toUpper();
    if (frame.hasExtendedFrameFormat())
        text = text.rightJustified(8, QLatin1Char('0'));
    else
        text = text.rightJustified(3, QLatin1Char('0'));
    const QByteArray data = frame.payload();
    if (!data.isEmpty())
        text += QLatin1Char(' ') + QString::fromLatin1(data.toHex(' ').toUpper());
    return text;
}

// The macro's steps in one line for the change log, shortened when long.
QString stepsText(const QList<SenderStep> &steps)
{
    constexpr int kMaxChars = 200;
    QStringList parts;
    for (const SenderStep &step : steps) {
        parts << (step.kind == SenderStep::Kind::Wait
                      ? QStringLiteral("wait %1").arg(step.waitMs)
                      : QStringLiteral("send %1").arg(frameText(step.frame)));
    }
    QString text = parts.join(QStringLiteral("; "));
    if (text.size() > kMaxChars)
        text = text.left(kMaxChars - 1) + QChar(0x2026);
    return text;
}

} // namespace

FrameSender::FrameSender(QWidget *parent)
    : QWidget(parent)
    , m_id(new QLineEdit(this))
    , m_data(new QLineEdit(this))
    , m_send(new QToolButton(this))
    , m_period(new QSpinBox(this))
    , m_periodic(new QToolButton(this))
    , m_macroToggle(new QToolButton(this))
    , m_macroBox(new QWidget(this))
    , m_macro(new QPlainTextEdit(m_macroBox))
    , m_run(new QPushButton(tr("Run"), m_macroBox))
    , m_status(new QLabel(this))
{
    m_id->setObjectName(QStringLiteral("sendId"));
    m_data->setObjectName(QStringLiteral("sendData"));
    m_send->setObjectName(QStringLiteral("send"));
    m_period->setObjectName(QStringLiteral("sendPeriod"));
    m_periodic->setObjectName(QStringLiteral("sendPeriodic"));
    m_macroToggle->setObjectName(QStringLiteral("macroToggle"));
    m_macro->setObjectName(QStringLiteral("macro"));
    m_run->setObjectName(QStringLiteral("runMacro"));
    m_status->setObjectName(QStringLiteral("sendStatus"));

    const int digit = fontMetrics().horizontalAdvance(QLatin1Char('0'));
    m_id->setFont(style::monospaceFont());
    m_id->setPlaceholderText(tr("ID"));
    m_id->setToolTip(tr("CAN identifier in hex (above 7FF: 29-bit)"));
    m_id->setMaximumWidth(digit * 10 + 16);
    m_data->setFont(style::monospaceFont());
    m_data->setPlaceholderText(tr("data bytes, e.g. 01 05"));
    m_data->setToolTip(tr("Up to 8 data bytes in hex"));
    m_data->setMinimumWidth(digit * 24 + 16);
    m_send->setText(tr("Send"));
    m_send->setToolTip(tr("Send the frame once"));
    m_period->setRange(1, 60000);
    m_period->setValue(100);
    m_period->setSuffix(tr(" ms"));
    m_period->setToolTip(tr("Period of periodic sending"));
    m_periodic->setText(tr("Periodic"));
    m_periodic->setCheckable(true);
    m_periodic->setToolTip(tr("Send the frame every period until switched off"));
    m_macroToggle->setText(tr("Macro…"));
    m_macroToggle->setCheckable(true);
    m_macroToggle->setToolTip(tr("A list of send ID DATA and wait MS lines"));
    m_macro->setFont(style::monospaceFont());
    m_macro->setPlaceholderText(
        tr("# one step a line\nsend 000 01 05\nwait 100\nsend 605 40 08 10 00"));
    m_macro->setMaximumHeight(m_macro->fontMetrics().height() * 6 + 10);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *row = new FlowLayout; // wraps in a narrow dock
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(4);
    row->addWidget(m_id);
    row->addWidget(m_data);
    row->addWidget(m_send);
    row->addWidget(m_period);
    row->addWidget(m_periodic);
    row->addWidget(m_macroToggle);
    row->addWidget(m_status);
    auto *macroLayout = new QHBoxLayout(m_macroBox);
    macroLayout->setContentsMargins(0, 0, 0, 0);
    macroLayout->addWidget(m_macro, 1);
    macroLayout->addWidget(m_run, 0, Qt::AlignTop);
    m_macroBox->hide();
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(row);
    layout->addWidget(m_macroBox);

    m_periodTimer.setTimerType(Qt::PreciseTimer);
    m_macroTimer.setSingleShot(true);
    m_macroTimer.setTimerType(Qt::PreciseTimer);
    connect(m_send, &QToolButton::clicked, this, &FrameSender::sendOnce);
    connect(m_data, &QLineEdit::returnPressed, this, &FrameSender::sendOnce);
    connect(m_periodic, &QToolButton::toggled, this, [this](bool on) {
        if (on != isPeriodic() && !setPeriodic(on))
            m_periodic->setChecked(false);
    });
    connect(m_period, &QSpinBox::valueChanged, this,
            [this](int ms) { m_periodTimer.setInterval(ms); });
    connect(&m_periodTimer, &QTimer::timeout, this, [this] {
        if (send(m_periodicFrame)) {
            ++m_periodicSent;
            return;
        }
        const QString cause = status();
        m_periodTimer.stop();
        const QSignalBlocker blocker(m_periodic);
        m_periodic->setChecked(false);
        record(
            frameText(m_periodicFrame),
            tr("every %1 ms: stopped after %n frame(s)", nullptr, m_periodicSent).arg(m_periodicMs),
            cause);
    });
    connect(m_macroToggle, &QToolButton::toggled, m_macroBox, &QWidget::setVisible);
    connect(m_run, &QPushButton::clicked, this, [this] {
        if (m_macroRunning)
            stopMacro();
        else
            runMacro();
    });
    connect(&m_macroTimer, &QTimer::timeout, this, &FrameSender::runSteps);
    updateButtons();
}

FrameSender::~FrameSender()
{
    finishMacroEntry(int(ChangeLog::Outcome::Aborted), tr("macro stopped"));
}

void FrameSender::setChangeLog(ChangeLog *log, const QString &device)
{
    m_changeLog = log;
    m_device = device;
}

int FrameSender::record(const QString &object, const QString &value, const QString &error)
{
    if (!m_changeLog)
        return 0;
    ChangeLog::Entry e;
    e.device = m_device;
    e.kind = ChangeLog::Kind::Frame;
    e.object = object;
    e.newValue = value;
    e.outcome = error.isEmpty() ? ChangeLog::Outcome::Ok : ChangeLog::Outcome::Failed;
    e.message = error;
    return m_changeLog->add(e);
}

void FrameSender::finishMacroEntry(int outcome, const QString &message)
{
    if (m_changeLog && m_macroEntry)
        m_changeLog->complete(m_macroEntry, ChangeLog::Outcome(outcome), message);
    m_macroEntry = 0;
}

void FrameSender::setBus(CanBus *bus)
{
    if (bus == m_bus)
        return;
    setPeriodic(false);
    stopMacro();
    m_bus = bus;
    updateButtons();
}

Result<QCanBusFrame> FrameSender::parseFrame(const QString &idText, const QString &dataText)
{
    QString id = idText.trimmed();
    if (id.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        id = id.mid(2);
    bool ok = false;
    const quint32 canId = id.toUInt(&ok, 16);
    if (id.isEmpty() || !ok || canId > kMaxExtendedId)
        return invalid(tr("'%1' is no CAN identifier (hex, 0..1FFFFFFF)").arg(idText.trimmed()));
    QString hex = dataText;
    hex.remove(QRegularExpression(QStringLiteral("[\\s,]")));
    static const QRegularExpression hexDigits(QStringLiteral("^[0-9A-Fa-f]*$"));
    if (!hexDigits.match(hex).hasMatch() || hex.size() % 2 != 0)
        return invalid(tr("'%1' are no data bytes (hex, e.g. 01 05)").arg(dataText.trimmed()));
    const QByteArray data = QByteArray::fromHex(hex.toLatin1());
    if (data.size() > 8)
        return invalid(tr("%1 data bytes; a CAN frame carries at most 8").arg(data.size()));
    QCanBusFrame frame(canId, data);
    frame.setExtendedFrameFormat(canId > kMaxStandardId || id.size() > 3);
    return frame;
}

Result<QList<SenderStep>> FrameSender::parseMacro(const QString &text)
{
    QList<SenderStep> steps;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines.at(i);
        if (const int hash = line.indexOf(QLatin1Char('#')); hash >= 0)
            line.truncate(hash);
        const QStringList words = line.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (words.isEmpty())
            continue;
        const QString command = words.first().toLower();
        const QString where = tr("line %1").arg(i + 1);
        if (command == QLatin1String("send")) {
            if (words.size() < 2)
                return invalid(tr("%1: send needs an ID and data bytes").arg(where));
            auto frame = parseFrame(words.at(1), words.mid(2).join(QLatin1Char(' ')));
            if (!frame)
                return frame.error().prefixed(where);
            steps.append({ SenderStep::Kind::Send, frame.value(), 0 });
        } else if (command == QLatin1String("wait")) {
            bool ok = false;
            const int ms = words.value(1).toInt(&ok);
            if (words.size() != 2 || !ok || ms < 0 || ms > kMaxWaitMs)
                return invalid(
                    tr("%1: wait takes milliseconds (0..%2)").arg(where).arg(kMaxWaitMs));
            SenderStep wait;
            wait.kind = SenderStep::Kind::Wait;
            wait.waitMs = ms;
            steps.append(wait);
        } else {
            return invalid(tr("%1: unknown command '%2' (send or wait)").arg(where, words.first()));
        }
    }
    return steps;
}

bool FrameSender::send(const QCanBusFrame &frame)
{
    if (!m_bus || !m_bus->isOpen()) {
        showStatus(tr("not sent: the bus is not open"), true);
        return false;
    }
    if (!m_bus->send(frame)) {
        showStatus(tr("not sent: the bus refused the frame"), true);
        return false;
    }
    ++m_sent;
    return true;
}

bool FrameSender::sendOnce()
{
    auto frame = parseFrame(m_id->text(), m_data->text());
    if (!frame) {
        showStatus(frame.error().message(), true);
        return false;
    }
    if (!send(frame.value())) {
        record(frameText(frame.value()), tr("once"), status());
        return false;
    }
    record(frameText(frame.value()), tr("once"), {});
    showStatus(tr("sent %1").arg(frame->toString()), false);
    return true;
}

bool FrameSender::setPeriodic(bool on)
{
    if (!on || isPeriodic()) { // a new frame or period: the old sending stops first
        if (isPeriodic()) {
            m_periodTimer.stop();
            record(frameText(m_periodicFrame),
                   tr("every %1 ms: stopped after %n frame(s)", nullptr, m_periodicSent)
                       .arg(m_periodicMs),
                   {});
        }
        const QSignalBlocker blocker(m_periodic);
        m_periodic->setChecked(false);
        if (!on)
            return true;
    }
    auto frame = parseFrame(m_id->text(), m_data->text());
    if (!frame) {
        showStatus(frame.error().message(), true);
        return false;
    }
    if (!m_bus || !m_bus->isOpen()) {
        showStatus(tr("not sent: the bus is not open"), true);
        return false;
    }
    m_periodicFrame = frame.value();
    m_periodicSent = 0;
    m_periodicMs = m_period->value();
    m_periodTimer.start(m_period->value());
    record(frameText(m_periodicFrame), tr("every %1 ms: started").arg(m_periodicMs), {});
    const QSignalBlocker blocker(m_periodic);
    m_periodic->setChecked(true);
    showStatus(tr("sending %1 every %2 ms").arg(frame->toString()).arg(m_period->value()), false);
    return true;
}

void FrameSender::setFrameText(const QString &id, const QString &data)
{
    m_id->setText(id);
    m_data->setText(data);
}

void FrameSender::setPeriodMs(int ms)
{
    m_period->setValue(ms);
}

void FrameSender::setMacroText(const QString &text)
{
    m_macro->setPlainText(text);
}

bool FrameSender::runMacro()
{
    auto steps = parseMacro(m_macro->toPlainText());
    if (!steps) {
        showStatus(steps.error().message(), true);
        return false;
    }
    if (!m_bus || !m_bus->isOpen()) {
        showStatus(tr("not sent: the bus is not open"), true);
        return false;
    }
    m_steps = std::move(steps).value();
    m_next = 0;
    m_macroRunning = true;
    if (m_changeLog) {
        ChangeLog::Entry e;
        e.device = m_device;
        e.kind = ChangeLog::Kind::Frame;
        e.object = tr("macro, %n step(s)", nullptr, int(m_steps.size()));
        e.newValue = stepsText(m_steps);
        m_macroEntry = m_changeLog->add(e);
    }
    updateButtons();
    runSteps();
    return true;
}

void FrameSender::stopMacro()
{
    if (!m_macroRunning)
        return;
    m_macroTimer.stop();
    m_macroRunning = false;
    updateButtons();
    showStatus(tr("macro stopped at step %1 of %2").arg(m_next).arg(m_steps.size()), false);
    finishMacroEntry(int(ChangeLog::Outcome::Aborted), status());
    Q_EMIT macroFinished(false);
}

void FrameSender::runSteps()
{
    while (m_macroRunning && m_next < m_steps.size()) {
        const SenderStep &step = m_steps.at(m_next++);
        if (step.kind == SenderStep::Kind::Wait) {
            m_macroTimer.start(step.waitMs);
            return;
        }
        if (!send(step.frame)) { // the cause is in the status line
            m_macroRunning = false;
            updateButtons();
            finishMacroEntry(int(ChangeLog::Outcome::Failed),
                             tr("step %1: %2").arg(m_next).arg(status()));
            Q_EMIT macroFinished(false);
            return;
        }
    }
    if (!m_macroRunning)
        return;
    m_macroRunning = false;
    updateButtons();
    showStatus(tr("macro done: %n step(s)", nullptr, int(m_steps.size())), false);
    finishMacroEntry(int(ChangeLog::Outcome::Ok), {});
    Q_EMIT macroFinished(true);
}

QString FrameSender::status() const
{
    return m_status->text();
}

void FrameSender::showStatus(const QString &text, bool error)
{
    m_status->setText(text);
    style::setTextColor(m_status, error ? style::errorColor() : style::inactiveColor());
}

void FrameSender::updateButtons()
{
    m_run->setText(m_macroRunning ? tr("Stop") : tr("Run"));
}

} // namespace db::widgets
