#pragma once

// Layer setting services (CiA 305) on a network through its LSS master: bring every slave into
// configuration mode or back to waiting, find an unconfigured one by fastscan, inquire the
// identity and node id of the slave in configuration mode, assign a node id or a bit rate and
// store them. One service at a time; each result is a line in the panel's log.

#include "core/result.h"

#include <QPointer>
#include <QWidget>

#include <functional>

class QComboBox;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;

namespace db {
class ChangeLog;
class Reply;
} // namespace db
namespace db::canopen {
class CanNetwork;
} // namespace db::canopen

namespace db::widgets {

class LssPanel : public QWidget
{
    Q_OBJECT
public:
    explicit LssPanel(QWidget *parent = nullptr);
    ~LssPanel() override;

    // Not owned; nullptr detaches.
    void setNetwork(canopen::CanNetwork *network);
    bool isBusy() const { return m_busy; }
    // Node id and bit rate assignments and stores go to this log. Not owned.
    void setChangeLog(ChangeLog *log);
    QString logText() const;

public Q_SLOTS:
    // Unconfirmed: every slave to configuration mode (true) or waiting (false).
    bool switchAll(bool configuration);
    // Each of these is false while busy or without an open bus; done() follows.
    bool fastscan();
    bool inquire();
    bool assignNodeId(int node);
    bool assignBitrate(int bitrate);
    bool store();

Q_SIGNALS:
    void done(bool ok);

private:
    bool ready();
    // Runs `reply`, then `then` with its result; logs failures with `what`.
    void run(Reply *reply, const QString &what,
             std::function<void(const QVariant &value)> then = {});
    void inquireNext(int cs, QStringList found);
    void log(const QString &text, bool error = false);
    // The change log entry for a setting sent to the slave in configuration mode.
    void record(Reply *reply, bool store, const QString &object, const QString &value);
    void setBusy(bool busy);

    QPointer<canopen::CanNetwork> m_network;
    QPointer<ChangeLog> m_changeLog;
    bool m_busy = false;
    QList<QPushButton *> m_buttons;
    QSpinBox *m_nodeId;
    QComboBox *m_bitrate;
    QPlainTextEdit *m_log;
};

} // namespace db::widgets
