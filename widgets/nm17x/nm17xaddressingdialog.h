#pragma once

// Guided broadcast addressing of a line of NM17x displays (all delivered as node 127): node ids
// are offered one after the other from the first one asked for; for each, the dialog tells the
// operator to turn the shaft (or press a key) of the display that should take it, counts down
// the time left, and lists every step's outcome. Cancel ends the addressing; the ids assigned so
// far stay. At the end every node is reset so that the new ids take effect, and the dialog says
// which ids were assigned.

#include "canopen/canopenids.h"

#include <QDialog>
#include <QElapsedTimer>
#include <QTimer>

class QDialogButtonBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace db::canopen {
class CanNetwork;
}
namespace db::nm17x {
class BroadcastAddressing;
}

namespace db::widgets {

class Nm17xAddressingDialog : public QDialog
{
    Q_OBJECT
public:
    // The network is not owned and must outlive the dialog.
    explicit Nm17xAddressingDialog(canopen::CanNetwork *network, QWidget *parent = nullptr);
    ~Nm17xAddressingDialog() override;

    void setFirstNode(canopen::NodeId node);
    // 0: until no display answers within the time of a step.
    void setCount(int count);
    void setStepSeconds(int seconds);
    // Same as Start / Cancel (the button also closes the dialog when nothing runs).
    void start();
    void cancel();

    bool isRunning() const;
    // What the operator is told now ("Turn the shaft of the display that should become node 3").
    QString instruction() const;
    // One line per step: "node 2: taken", "node 5: no display answered within 60 s".
    QStringList steps() const;
    QList<canopen::NodeId> assignedIds() const;

Q_SIGNALS:
    // After the final reset; ok = every step asked for was taken (or cancelled cleanly).
    void addressingFinished(bool ok);

protected:
    void reject() override;

private:
    void onOffering(canopen::NodeId node);
    void onAssigned(canopen::NodeId node);
    void onFinished(bool ok);
    void updateCountdown();
    void addStep(const QString &text, bool error = false);
    void setRunning(bool running);

    canopen::CanNetwork *m_network;
    nm17x::BroadcastAddressing *m_addressing;
    QSpinBox *m_first;
    QSpinBox *m_count;
    QSpinBox *m_stepSeconds;
    QLabel *m_instruction;
    QLabel *m_countdown;
    QProgressBar *m_progress;
    QListWidget *m_steps;
    QPushButton *m_start;
    QPushButton *m_cancel;
    QTimer m_tick;
    QElapsedTimer m_stepClock;
    canopen::NodeId m_offered = 0;
    bool m_running = false;
};

} // namespace db::widgets
