// JogPanel: the drive's limits (read by its axis) in the command model's AxisConfig, and what
// stops the drive when drivebench goes away.
#include "jogpanel.h"

#include "motionform.h"

#include <QDoubleSpinBox>
#include <QLabel>

#include <memory>

namespace db::widgets {

using namespace motion;

void JogPanel::applyLimits()
{
    if (!m_motion || !m_connection)
        return;
    m_config = m_cia->limits();
    m_motion->setConfig(m_config);
    m_limitsKnown = true;
    m_form->setLimits(m_config, m_positionUnit, m_velocityUnit);
    renderLimits();
    renderSupervision();
}

QVariantMap JogPanel::settings() const
{
    QVariantMap values = m_form->values();
    values.insert(QStringLiteral("jogVelocity"), m_jogVelocity->value());
    values.insert(QStringLiteral("jogAcceleration"), m_jogAcceleration->value());
    values.insert(QStringLiteral("stepSize"), m_stepSize->value());
    return values;
}

void JogPanel::applySettings(const QVariantMap &values)
{
    m_form->setValues(values);
    for (QDoubleSpinBox *box : { m_jogVelocity, m_jogAcceleration, m_stepSize }) {
        if (const QVariant v = values.value(box->objectName()); v.isValid()) {
            box->setMaximum(1e9); // the previous drive's limit does not apply to this one
            box->setValue(v.toDouble());
        }
    }
}

void JogPanel::keepSettingsFor(DeviceConnection *next)
{
    const QString key = next ? next->uri().toString() : QString();
    if (key == m_settingsKey || (!next && m_settingsKey.isEmpty()))
        return;
    if (!m_settingsKey.isEmpty())
        m_kept.insert(m_settingsKey, settings());
    if (!next)
        return; // the values stay shown (greyed) until the next device
    m_settingsKey = key;
    applySettings(m_kept.value(key, m_defaults));
}

void JogPanel::setDeviceResponding(bool responding, const QString &why)
{
    const bool answeredAgain = responding && !m_responding;
    m_responding = responding;
    m_silentWhy = why;
    if (answeredAgain && !m_limitsKnown && m_connection && m_connection->isConnected())
        onInitialized(nullptr, m_generation);
    render();
}

} // namespace db::widgets

namespace db::widgets {

void JogPanel::renderSupervision()
{
    if (!m_connection) {
        m_supervision->clear();
        return;
    }
    const QString lease = tr("Jog and step move in leases of %1 ms plus the braking distance: "
                             "the drive stops by itself when the renewals stop.")
                              .arg(motion::LeasedMove::kLeaseMs);
    QString drive;
    if (!m_driveSupervision && m_cia && !m_cia->linkSupervision().isEmpty())
        drive = m_cia->linkSupervision();
    else if (!m_driveSupervision)
        drive = tr("No drive-side supervision on this connection.");
    else if (m_driveSupervision->isArmed())
        drive = tr("Active: %1.").arg(m_driveSupervision->description());
    else
        drive = tr("On enable: %1.").arg(m_driveSupervision->description());
    m_supervision->setText(lease + QLatin1Char('\n') + drive);
}

void JogPanel::releaseSupervision()
{
    auto supervision = std::move(m_driveSupervision);
    if (!supervision || !supervision->isArmed() || !m_connection || !m_connection->isConnected())
        return; // destroyed unarmed, or our side just stops: the drive reacts as to a lost master
    // A clean let-go: the drive's previous settings go back; the object lives until then.
    canopen::DriveSupervision *s = supervision.release();
    s->setParent(m_connection);
    Reply *r = s->disarm();
    connect(r, &Reply::finished, s, [r, s] {
        r->deleteLater();
        s->deleteLater();
    });
}

} // namespace db::widgets
