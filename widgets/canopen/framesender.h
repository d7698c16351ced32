#pragma once

// The CAN monitor's frame sender: one frame typed as ID and data bytes (hex), sent once or every
// period, and a macro of `send ID DATA` / `wait MS` lines run top to bottom (one line a step;
// `#` starts a comment). Frames go out through the bus given; nothing is sent while it is closed.
// With a change log, each action is one entry: a frame sent once, the start and the stop of
// periodic sending, a macro from its start to its end (never one entry per frame).

#include "core/result.h"

#include <QCanBusFrame>
#include <QPointer>
#include <QTimer>
#include <QWidget>

class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;
class QToolButton;

namespace db {
class CanBus;
class ChangeLog;
} // namespace db

namespace db::widgets {

struct SenderStep
{
    enum class Kind { Send, Wait };
    Kind kind = Kind::Send;
    QCanBusFrame frame; // Send
    int waitMs = 0; // Wait
};

class FrameSender : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kMaxWaitMs = 3600 * 1000;

    explicit FrameSender(QWidget *parent = nullptr);
    ~FrameSender() override;

    // Not owned; nullptr detaches (periodic sending and a running macro stop).
    void setBus(CanBus *bus);
    CanBus *bus() const { return m_bus; }
    // Not owned; `device` names the bus in the entries (the connection's URI).
    void setChangeLog(ChangeLog *log, const QString &device);

    // "601" / "0x18FF0001" (hex; above 7FF a 29-bit id) and "40 00 10 00" or "40001000" (hex,
    // up to 8 bytes). InvalidArgument names what is wrong.
    static Result<QCanBusFrame> parseFrame(const QString &id, const QString &data);
    // The macro's steps; InvalidArgument names the line ("line 3: ...").
    static Result<QList<SenderStep>> parseMacro(const QString &text);

    // The fields' frame, once; false (the cause in status()) when they do not parse or the bus
    // is closed.
    bool sendOnce();
    // Sends the fields' frame every period() ms while on. False when the fields do not parse.
    bool setPeriodic(bool on);
    bool isPeriodic() const { return m_periodTimer.isActive(); }
    void setFrameText(const QString &id, const QString &data);
    void setPeriodMs(int ms);
    void setMacroText(const QString &text);
    bool runMacro();
    void stopMacro();
    bool isMacroRunning() const { return m_macroRunning; }
    // Frames this sender put on the bus so far.
    int sentCount() const { return m_sent; }
    QString status() const;

Q_SIGNALS:
    void macroFinished(bool completed);

private:
    bool send(const QCanBusFrame &frame);
    void runSteps();
    void showStatus(const QString &text, bool error);
    void updateButtons();
    // Adds a finished entry for a send action; returns its id.
    int record(const QString &object, const QString &value, const QString &error);
    void finishMacroEntry(int outcome, const QString &message);

    QPointer<CanBus> m_bus;
    QLineEdit *m_id;
    QLineEdit *m_data;
    QToolButton *m_send;
    QSpinBox *m_period;
    QToolButton *m_periodic;
    QToolButton *m_macroToggle;
    QWidget *m_macroBox;
    QPlainTextEdit *m_macro;
    QPushButton *m_run;
    QLabel *m_status;
    QTimer m_periodTimer;
    QCanBusFrame m_periodicFrame;
    QTimer m_macroTimer;
    QList<SenderStep> m_steps;
    int m_next = 0;
    bool m_macroRunning = false;
    int m_sent = 0;
    QPointer<ChangeLog> m_changeLog;
    QString m_device;
    int m_periodicSent = 0; // frames of the running periodic sending
    int m_periodicMs = 0;
    int m_macroEntry = 0; // the running macro's pending entry
};

} // namespace db::widgets
