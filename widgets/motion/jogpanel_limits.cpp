// JogPanel: reading the drive's limits into the command model's AxisConfig (motion/axislimits.h)
// and what stops the drive when drivebench goes away.
#include "jogpanel.h"

#include "motion/axislimits.h"
#include "motionform.h"

#include <QLabel>

#include <memory>

namespace db::widgets {

using namespace motion;

bool JogPanel::rotaryAcceleration() const
{
    // MovingCap rotary drives give accelerations in [100 rpm/min] of the motor (movingcap.md
    // 9.1); the panel's fields are user units/s^2 either way.
    return m_connection
        && m_connection->dictionary().identity.productName.contains(QLatin1String("MovingCap"),
                                                                    Qt::CaseInsensitive);
}

void JogPanel::readLimits(quint64 generation)
{
    // A failed read leaves that limit at its default (none).
    const QList<ObjectAddress> wanted = axislimits::objects(m_connection->dictionary());
    if (wanted.isEmpty()) {
        applyLimits({});
        return;
    }
    auto values = std::make_shared<QHash<ObjectAddress, QVariant>>();
    auto pending = std::make_shared<int>(int(wanted.size()));
    for (ObjectAddress a : wanted) {
        Reply *r = m_connection->read(a);
        connect(r, &Reply::finished, this, [=, this] {
            r->deleteLater();
            if (r->ok())
                values->insert(a, r->value());
            if (--*pending != 0 || generation != m_generation)
                return;
            if (values->isEmpty()) {
                // Nothing answered: no limits from a drive that never replied (the
                // description's defaults are not the drive's values). Read again once it answers.
                m_limits->setText(tr("The drive did not answer: its limits are not known yet."));
                return;
            }
            applyLimits(*values);
        });
    }
}

void JogPanel::applyLimits(const QHash<ObjectAddress, QVariant> &values)
{
    if (!m_motion || !m_connection)
        return;
    m_config = axislimits::fromValues(values, m_connection->dictionary(), m_cia->scaling(),
                                      rotaryAcceleration());
    m_motion->setConfig(m_config);
    m_limitsKnown = true;
    m_form->setLimits(m_config, m_positionUnit, m_velocityUnit);
    renderLimits();
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
    if (!m_driveSupervision)
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
