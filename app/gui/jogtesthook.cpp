#include "jogtesthook.h"

#include "mainwindow.h"

#include "widgets/motion/jogpanel.h"

#include <QApplication>
#include <QDoubleSpinBox>
#include <QMouseEvent>
#include <QPushButton>
#include <QTimer>

#include <cstdio>

namespace db::gui {

namespace {
constexpr int kPollMs = 50;

struct HoldJog
{
    double velocity = 0.0;
    double ramp = 0.0; // 0: the panel's own
};

bool parse(const QByteArray &value, HoldJog &out)
{
    const QList<QByteArray> parts = value.split(',');
    bool ok = parts.size() <= 2;
    out.velocity = ok ? parts.at(0).toDouble(&ok) : 0.0;
    if (ok && parts.size() == 2)
        out.ramp = parts.at(1).toDouble(&ok);
    return ok && out.velocity != 0.0 && out.ramp >= 0.0;
}

void press(QPushButton *button)
{
    const QPointF at = QRectF(button->rect()).center();
    QMouseEvent event(QEvent::MouseButtonPress, at, button->mapToGlobal(at), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(button, &event);
}
} // namespace

void holdJogFromEnvironment(MainWindow &window)
{
    const QByteArray value = qgetenv("DRIVEBENCH_TEST_HOLD_JOG");
    if (value.isEmpty())
        return;
    HoldJog hold;
    if (!parse(value, hold)) {
        std::fprintf(stderr,
                     "drivebench: DRIVEBENCH_TEST_HOLD_JOG takes VELOCITY[,RAMP], not '%s'; "
                     "ignored\n",
                     value.constData());
        return;
    }
    widgets::JogPanel *panel = window.jogPanel();
    auto *timer = new QTimer(panel);
    timer->setInterval(kPollMs);
    QObject::connect(
        timer, &QTimer::timeout, panel, [panel, timer, hold, enabled = false]() mutable {
            motion::MotionAxis *axis = panel->motionAxis();
            // After a first status round: a drive enabled before is not enabled again.
            if (!axis || !panel->limitsKnown() || !panel->isDeviceResponding()
                || !panel->axis()->status().valid)
                return;
            if (axis->state() == motion::AxisState::Disabled) {
                if (!enabled)
                    panel->findChild<QPushButton *>(QStringLiteral("enable"))->click();
                enabled = true;
                return;
            }
            if (axis->state() != motion::AxisState::Standstill)
                return;
            timer->stop();
            timer->deleteLater();
            panel->findChild<QDoubleSpinBox *>(QStringLiteral("jogVelocity"))
                ->setValue(qAbs(hold.velocity));
            if (hold.ramp > 0)
                panel->findChild<QDoubleSpinBox *>(QStringLiteral("jogAcceleration"))
                    ->setValue(hold.ramp);
            QPushButton *jog = panel->findChild<QPushButton *>(
                hold.velocity > 0 ? QStringLiteral("jogPlus") : QStringLiteral("jogMinus"));
            press(jog);
            std::fprintf(stderr, "drivebench: test hook: holding %s at %g units/s\n",
                         hold.velocity > 0 ? "Jog +" : "Jog -", qAbs(hold.velocity));
        });
    timer->start();
}

} // namespace db::gui
