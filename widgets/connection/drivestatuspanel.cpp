#include "drivestatuspanel.h"

#include "widgets/common/lamp.h"
#include "widgets/common/widgetstyle.h"

#include <QDateTime>
#include <QLabel>

namespace db::widgets {

namespace {

constexpr ObjectAddress kStatusword { 0x6041, 0 };
constexpr ObjectAddress kModeDisplay { 0x6061, 0 };
constexpr ObjectAddress kPosition { 0x6064, 0 };
constexpr ObjectAddress kVelocity { 0x606C, 0 };
constexpr ObjectAddress kCurrent { 0x6078, 0 };
constexpr ObjectAddress kStatusRegister { 0x1002, 0 };
constexpr ObjectAddress kErrorCode { 0x603F, 0 };
constexpr ObjectAddress kInputs { 0x60FD, 0 };
constexpr ObjectAddress kOutputs { 0x60FE, 1 };

constexpr int kIoFirstBit = 16; // IN1 = 60FDh bit 16, OUT1 = 60FEh.1 bit 16 (movingcap.md 6.5)
constexpr int kErrorBitCount = 16; // 1002h bits 0-15 are errors, 16+ warnings (movingcap.md 7.2)

QColor stateColor(cia402::State state)
{
    switch (state) {
    case cia402::State::OperationEnabled:
        return style::okColor();
    case cia402::State::Fault:
    case cia402::State::FaultReactionActive:
        return style::errorColor();
    case cia402::State::QuickStopActive:
        return style::warningColor();
    default:
        return QColor(0x45, 0x5a, 0x64);
    }
}

} // namespace

DriveStatusPanel::DriveStatusPanel(QWidget *parent)
    : QWidget(parent)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &DriveStatusPanel::startCycle);
    buildUi();
    markAllStale();
}

QList<ObjectAddress> DriveStatusPanel::polledObjects()
{
    return { kStatusword,     kModeDisplay, kPosition, kVelocity, kCurrent,
             kStatusRegister, kErrorCode,   kInputs,   kOutputs };
}

QString DriveStatusPanel::stateText(cia402::State state)
{
    switch (state) {
    case cia402::State::NotReadyToSwitchOn:
        return tr("Not ready to switch on");
    case cia402::State::SwitchOnDisabled:
        return tr("Switch on disabled");
    case cia402::State::ReadyToSwitchOn:
        return tr("Ready to switch on");
    case cia402::State::SwitchedOn:
        return tr("Switched on");
    case cia402::State::OperationEnabled:
        return tr("Operation enabled");
    case cia402::State::QuickStopActive:
        return tr("Quick stop active");
    case cia402::State::FaultReactionActive:
        return tr("Fault reaction active");
    case cia402::State::Fault:
        return tr("Fault");
    case cia402::State::Unknown:
        break;
    }
    return tr("Unknown state");
}

void DriveStatusPanel::setConnection(DeviceConnection *connection)
{
    if (connection && m_connection == connection)
        return;
    for (const auto &c : std::as_const(m_connectionSignals))
        disconnect(c);
    m_connectionSignals.clear();
    ++m_generation; // replies still in flight belong to the old connection
    m_pending = 0;
    m_timer.stop();
    m_values.clear();
    m_errors.clear();
    m_connection = connection;
    if (connection) {
        m_connectionSignals = {
            connect(connection, &DeviceConnection::stateChanged, this,
                    &DriveStatusPanel::onStateChanged),
            // A destroyed connection is forgotten as if setConnection(nullptr) was called.
            connect(connection, &QObject::destroyed, this, [this] { setConnection(nullptr); }),
        };
    }
    onStateChanged();
}

void DriveStatusPanel::setPollInterval(int ms)
{
    m_intervalMs = qMax(10, ms);
    if (m_timer.isActive())
        m_timer.start(m_intervalMs);
}

void DriveStatusPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    scheduleNext(0);
}

void DriveStatusPanel::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_timer.stop(); // a cycle in flight finishes; scheduleNext() then does nothing
}

void DriveStatusPanel::onStateChanged()
{
    if (m_connection && m_connection->isConnected()) {
        scheduleNext(0);
        return;
    }
    m_timer.stop();
    markAllStale();
}

void DriveStatusPanel::scheduleNext(int delayMs)
{
    if (m_pending > 0 || !m_connection || !m_connection->isConnected() || !isVisible())
        return;
    m_timer.start(delayMs);
}

void DriveStatusPanel::startCycle()
{
    if (m_pending > 0 || !m_connection || !m_connection->isConnected() || !isVisible())
        return;
    // Only what the description has: a device without these objects would answer every round
    // with errors (SDO aborts) and tell nothing.
    const ObjectDictionary &dictionary = m_connection->dictionary();
    QList<ObjectAddress> objects = polledObjects();
    objects.removeIf([&dictionary](ObjectAddress a) { return !dictionary.contains(a); });
    m_fresh.clear();
    m_errors.clear();
    if (objects.isEmpty()) {
        render();
        m_footer->setText(dictionary.isEmpty()
                              ? tr("Nothing is read: the device has no description.")
                              : tr("Nothing is read: the description has no drive status "
                                   "objects."));
        Q_EMIT cycleFinished();
        scheduleNext(m_intervalMs);
        return;
    }
    m_pending = int(objects.size());
    const quint64 generation = m_generation;
    for (ObjectAddress address : objects) {
        Reply *reply = m_connection->read(address);
        reply->setParent(this); // deleted with the panel if it never finishes in time
        connect(reply, &Reply::finished, this,
                [this, reply, generation] { onReplyFinished(reply, generation); });
    }
}

void DriveStatusPanel::onReplyFinished(Reply *reply, quint64 generation)
{
    reply->deleteLater();
    if (generation != m_generation)
        return;
    if (reply->ok()) {
        m_values.insert(reply->address(), reply->value());
        m_fresh.insert(reply->address());
    } else {
        m_errors.insert(reply->address(), reply->error().toString());
    }
    if (--m_pending > 0)
        return;
    if (m_connection && m_connection->isConnected())
        render();
    else
        markAllStale(); // the link went away during the cycle
    Q_EMIT cycleFinished();
    scheduleNext(m_intervalMs);
}

void DriveStatusPanel::markAllStale()
{
    m_fresh.clear();
    render();
    if (!m_connection)
        m_footer->setText(tr("No device selected."));
    else if (!m_connection->isConnected())
        m_footer->setText(
            tr("%1 is %2.").arg(m_connection->uri().toString(), stateName(m_connection->state())));
}

void DriveStatusPanel::render()
{
    renderState();
    renderValues();
    renderFaults();
    renderIo();
    if (!m_errors.isEmpty()) {
        const auto first = m_errors.constBegin();
        m_footer->setText(tr("%n read(s) failed; %1: %2", nullptr, int(m_errors.size()))
                              .arg(first.key().toString(), first.value()));
    } else if (!m_fresh.isEmpty()) {
        m_footer->setText(tr("Updated %1, every %2 ms")
                              .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")))
                              .arg(m_intervalMs));
    }
}

QString DriveStatusPanel::valueText(ObjectAddress address) const
{
    const QVariant raw = m_values.value(address);
    if (!raw.isValid())
        return QStringLiteral("—");
    const ObjectDef *def = m_connection ? m_connection->dictionary().find(address) : nullptr;
    return def ? def->displayText(raw) : raw.toString();
}

void DriveStatusPanel::renderState()
{
    const QVariant raw = m_values.value(kStatusword);
    const bool stale = isStale(kStatusword);
    const auto sw = quint16(raw.toUInt());
    const cia402::State state = raw.isValid() ? cia402::decodeState(sw) : cia402::State::Unknown;
    m_stateLabel->setText(raw.isValid() ? stateText(state) : tr("No status"));
    const QColor badge = raw.isValid() && !stale ? stateColor(state) : style::inactiveColor();
    m_stateLabel->setStyleSheet(
        QStringLiteral("QLabel { color: white; background: %1; border-radius: 5px; "
                       "padding: 8px 16px; }")
            .arg(badge.name()));
    m_stateLabel->setToolTip(m_errors.value(kStatusword));
    m_statuswordLabel->setText(raw.isValid()
                                   ? QStringLiteral("0x%1").arg(sw, 4, 16, QLatin1Char('0'))
                                   : QStringLiteral("—"));
    style::setStale(m_statuswordLabel, stale);
    for (Lamp *lamp : std::as_const(m_bitLamps)) {
        if (raw.isValid())
            lamp->setOn(sw & lamp->property("mask").toUInt());
        lamp->setStale(stale);
    }

    const QVariant mode = m_values.value(kModeDisplay);
    m_modeLabel->setText(
        mode.isValid()
            ? QStringLiteral("%1 (%2)").arg(cia402::modeName(mode.toInt())).arg(mode.toInt())
            : QStringLiteral("—"));
    style::setStale(m_modeLabel, isStale(kModeDisplay));
}

void DriveStatusPanel::renderValues()
{
    const std::pair<QLabel *, ObjectAddress> rows[] = { { m_positionLabel, kPosition },
                                                        { m_velocityLabel, kVelocity },
                                                        { m_currentLabel, kCurrent } };
    for (const auto &[label, address] : rows) {
        label->setText(valueText(address));
        label->setToolTip(m_errors.value(address));
        style::setStale(label, isStale(address));
    }
}

void DriveStatusPanel::renderFaults()
{
    const QVariant reg = m_values.value(kStatusRegister);
    const quint32 bits = reg.toUInt();
    m_registerLabel->setText(reg.isValid()
                                 ? QStringLiteral("0x%1").arg(bits, 8, 16, QLatin1Char('0'))
                                 : QStringLiteral("—"));
    m_registerLabel->setToolTip(m_errors.value(kStatusRegister));
    style::setStale(m_registerLabel, isStale(kStatusRegister));

    const ObjectDef *def =
        m_connection ? m_connection->dictionary().find(kStatusRegister) : nullptr;
    QStringList errors;
    QStringList warnings;
    for (int bit = 0; bit < 32; ++bit) {
        if (!(bits & (1u << bit)))
            continue;
        QString name = tr("bit %1").arg(bit);
        if (def) {
            for (const BitField &field : def->bitFields) {
                if (field.bit == bit)
                    name = field.name;
            }
        }
        (bit < kErrorBitCount ? errors : warnings).append(name);
    }
    const bool stale = isStale(kStatusRegister);
    if (reg.isValid() && errors.isEmpty() && warnings.isEmpty())
        m_registerBitsLabel->setText(tr("No error or warning bits"));
    else
        m_registerBitsLabel->setText(errors.join(QLatin1Char('\n')));
    m_registerBitsLabel->setVisible(!m_registerBitsLabel->text().isEmpty());
    m_warningBitsLabel->setText(warnings.join(QLatin1Char('\n')));
    m_warningBitsLabel->setVisible(!warnings.isEmpty());
    style::setTextColor(m_registerBitsLabel,
                        stale                  ? style::inactiveColor()
                            : errors.isEmpty() ? QColor()
                                               : style::errorColor());
    style::setTextColor(m_warningBitsLabel, stale ? style::inactiveColor() : style::warningColor());

    const QVariant code = m_values.value(kErrorCode);
    const quint32 c = code.toUInt();
    QString codeText = QStringLiteral("—");
    QString text;
    if (code.isValid() && c == 0) {
        codeText = QStringLiteral("0x0000");
        text = tr("No error");
    } else if (code.isValid()) {
        codeText = QStringLiteral("0x%1").arg(c, 4, 16, QLatin1Char('0'));
        if (m_connection) {
            if (const auto known = m_connection->dictionary().errorCode(c))
                codeText += QLatin1Char(' ') + known->name;
            text = m_connection->dictionary().errorText(c);
        }
    }
    m_lastErrorLabel->setText(codeText);
    m_lastErrorLabel->setToolTip(m_errors.value(kErrorCode));
    m_lastErrorText->setText(text);
    style::setStale(m_lastErrorLabel, isStale(kErrorCode));
    style::setTextColor(m_lastErrorText, isStale(kErrorCode) ? style::inactiveColor() : QColor());
}

void DriveStatusPanel::renderIo()
{
    const auto update = [this](const QList<Lamp *> &lamps, ObjectAddress address) {
        const QVariant raw = m_values.value(address);
        for (int i = 0; i < lamps.size(); ++i) {
            if (raw.isValid())
                lamps[i]->setOn(raw.toULongLong() & (1ull << (kIoFirstBit + i)));
            lamps[i]->setStale(isStale(address));
            lamps[i]->setToolTip(m_errors.value(address));
        }
    };
    update(m_inputLamps, kInputs);
    update(m_outputLamps, kOutputs);
}

} // namespace db::widgets
