// JogPanel: reading the drive's limits into the command model's AxisConfig (motion/axislimits.h).
#include "jogpanel.h"

#include "motion/axislimits.h"
#include "motionform.h"

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
            if (--*pending == 0 && generation == m_generation)
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

} // namespace db::widgets
