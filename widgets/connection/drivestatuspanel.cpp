#include "drivestatuspanel.h"

#include "cia402/cia402statussource.h"
#include "widgets/common/lamp.h"
#include "widgets/common/widgetstyle.h"

#include <QLabel>
#include <QTime>

namespace db::widgets {

namespace {

QColor stateColor(StatusSource::State state)
{
    switch (state) {
    case StatusSource::State::OperationEnabled:
        return style::okColor();
    case StatusSource::State::Fault:
    case StatusSource::State::FaultReactionActive:
        return style::errorColor();
    case StatusSource::State::QuickStopActive:
        return style::warningColor();
    default:
        return QColor(0x45, 0x5a, 0x64);
    }
}

void showValue(QLabel *label, const StatusValue &value)
{
    label->setText(value.text.isEmpty() ? QStringLiteral("—") : value.text);
    label->setToolTip(value.error);
    style::setStale(label, !value.fresh);
}

} // namespace

DriveStatusPanel::DriveStatusPanel(QWidget *parent)
    : QWidget(parent)
{
    buildUi();
    buildFamilyUi();
    render();
}

DriveStatusPanel::~DriveStatusPanel()
{
    hold(false);
}

QList<ObjectAddress> DriveStatusPanel::polledObjects()
{
    return cia402::Cia402StatusSource::objects();
}

void DriveStatusPanel::setConnection(DeviceConnection *connection)
{
    if (connection && m_connection == connection)
        return;
    hold(false);
    for (const auto &c : std::as_const(m_signals))
        disconnect(c);
    m_signals.clear();
    m_connection = connection;
    m_source = nullptr;
    if (connection) {
        m_source = cia402::Cia402StatusSource::sourceOf(connection);
        m_source->setIntervalMs(m_intervalMs);
        m_signals = {
            connect(m_source, &StatusSource::updated, this, &DriveStatusPanel::onUpdated),
            connect(connection, &DeviceConnection::stateChanged, this,
                    &DriveStatusPanel::onStateChanged),
            // A destroyed connection is forgotten as if setConnection(nullptr) was called.
            connect(connection, &QObject::destroyed, this, [this] { setConnection(nullptr); }),
        };
    }
    buildFamilyUi();
    hold(isVisible());
    onStateChanged();
}

void DriveStatusPanel::setPollInterval(int ms)
{
    m_intervalMs = qMax(10, ms);
    if (m_source)
        m_source->setIntervalMs(m_intervalMs);
}

void DriveStatusPanel::hold(bool on)
{
    if (on == m_held || (on && !m_source))
        return;
    m_held = on;
    if (!m_source)
        return;
    if (on)
        m_source->acquire();
    else
        m_source->release();
}

void DriveStatusPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    hold(true);
}

void DriveStatusPanel::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    hold(false); // a cycle in flight finishes; then the source stops unless others hold it
}

void DriveStatusPanel::onStateChanged()
{
    render();
}

void DriveStatusPanel::onUpdated()
{
    render();
    if (m_connection && m_connection->isConnected())
        Q_EMIT cycleFinished();
}

void DriveStatusPanel::render()
{
    renderState();
    renderValues();
    renderFaults();
    renderIo();
    renderFooter();
}

void DriveStatusPanel::renderFooter()
{
    if (!m_connection) {
        style::setFrequentText(m_footer, tr("No device selected."));
    } else if (!m_connection->isConnected()) {
        style::setFrequentText(
            m_footer,
            tr("%1 is %2.").arg(m_connection->uri().toString(), stateName(m_connection->state())));
    } else if (m_source && !m_source->errors().isEmpty()) {
        const auto first = m_source->errors().constBegin();
        style::setFrequentText(
            m_footer,
            tr("%n read(s) failed; %1: %2", nullptr, int(m_source->errors().size()))
                .arg(m_connection->addressFormat().format(first.key()), first.value()));
    } else if (m_source && m_source->cycles() > 0) {
        style::setFrequentText(m_footer,
                               tr("Updated %1, every %2 ms")
                                   .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")))
                                   .arg(m_intervalMs));
    }
}

void DriveStatusPanel::renderState()
{
    const StatusValue word = m_source ? m_source->statusWordValue() : StatusValue();
    const bool valid = word.raw.isValid();
    const bool stale = !word.fresh;
    const StatusSource::State state = m_source ? m_source->state() : StatusSource::State::Unknown;
    m_stateLabel->setText(valid ? StatusSource::stateText(state) : tr("No status"));
    const QColor badge = valid && !stale ? stateColor(state) : style::inactiveColor();
    // A style sheet set again re-polishes the label and lays out the whole window: only when the
    // colour changes.
    const QString sheet = QStringLiteral("QLabel { color: white; background: %1; "
                                         "border-radius: 5px; padding: 8px 16px; }")
                              .arg(badge.name());
    if (m_stateLabel->styleSheet() != sheet)
        m_stateLabel->setStyleSheet(sheet);
    m_stateLabel->setToolTip(word.error);
    showValue(m_statuswordLabel, word);
    const quint32 sw = quint32(word.raw.toULongLong());
    for (Lamp *lamp : std::as_const(m_bitLamps)) {
        if (valid)
            lamp->setOn(sw & lamp->property("mask").toUInt());
        lamp->setStale(stale);
    }
    if (m_source && !m_source->mode().key.isEmpty())
        showValue(m_modeLabel, m_source->mode());
}

void DriveStatusPanel::renderValues()
{
    if (!m_source)
        return;
    const QList<StatusValue> values = m_source->actualValues();
    for (qsizetype i = 0; i < values.size() && i < m_valueLabels.size(); ++i)
        showValue(m_valueLabels[i], values[i]);
}

void DriveStatusPanel::renderFaults()
{
    if (!m_source) {
        m_lastErrorLabel->setText(QStringLiteral("—"));
        m_lastErrorText->clear();
        m_registerBitsLabel->hide();
        m_warningBitsLabel->clear();
        m_linkLossLabel->hide();
        return;
    }
    const StatusValue reg = m_source->faultRegister();
    const QStringList errors = m_source->errorBits();
    const QStringList warnings = m_source->warnings();
    if (!reg.key.isEmpty()) {
        showValue(m_registerLabel, reg);
        if (reg.raw.isValid() && errors.isEmpty() && warnings.isEmpty())
            m_registerBitsLabel->setText(tr("No error or warning bits"));
        else
            m_registerBitsLabel->setText(errors.join(QLatin1Char('\n')));
        style::setTextColor(m_registerBitsLabel,
                            !reg.fresh             ? style::inactiveColor()
                                : errors.isEmpty() ? QColor()
                                                   : style::errorColor());
    } else {
        m_registerBitsLabel->clear();
    }
    m_registerBitsLabel->setVisible(!m_registerBitsLabel->text().isEmpty());

    const StatusValue fault = m_source->fault();
    showValue(m_lastErrorLabel, fault);
    m_lastErrorText->setText(m_source->faultText());
    style::setTextColor(m_lastErrorText,
                        !fault.fresh                  ? style::inactiveColor()
                            : m_source->faultActive() ? style::errorColor()
                                                      : QColor());

    m_warningBitsLabel->setText(warnings.isEmpty() ? tr("none") : warnings.join(QLatin1Char('\n')));
    // Only the warnings are stale-greyed with the fault; their source objects vary by family.
    style::setTextColor(m_warningBitsLabel,
                        !fault.fresh             ? style::inactiveColor()
                            : warnings.isEmpty() ? QColor()
                                                 : style::warningColor());

    const QString linkLoss = m_source->linkLossText();
    m_linkLossLabel->setText(linkLoss);
    m_linkLossLabel->setVisible(!linkLoss.isEmpty());
}

void DriveStatusPanel::renderIo()
{
    if (!m_source)
        return;
    const QList<StatusIoRow> rows = m_source->ioRows();
    for (qsizetype r = 0; r < rows.size() && r < m_ioLamps.size(); ++r) {
        const QVariant raw = m_source->value(rows[r].address);
        const bool stale = !m_source->isFresh(rows[r].address);
        const QString error = m_source->errors().value(rows[r].address);
        const QList<Lamp *> &lamps = m_ioLamps[r];
        for (qsizetype i = 0; i < lamps.size(); ++i) {
            if (raw.isValid())
                lamps[i]->setOn(raw.toULongLong() & (1ull << (rows[r].firstBit + i)));
            lamps[i]->setStale(stale);
            lamps[i]->setToolTip(error);
        }
    }
}

} // namespace db::widgets
