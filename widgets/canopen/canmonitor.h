#pragma once

// The CAN monitor dock: live frames of one CanBus with their CANopen reading,
// Kickdrive-style filters (COB-ID ranges, direction, object index, data pattern with ??
// wildcards, text), pause, clear, autoscroll and saving as a candump log.
//
// It receives a bus (or a connection to a CANopen node, for its network's bus and its dictionary)
// and never creates one.
// Pause freezes the table; frames keep being captured and appear on resume (CanMonitorModel).
// Save writes the frames the filters let through, atomically (QSaveFile).
// Below the table a FrameSender puts frames on the same bus (once, periodic, or a macro).

#include "canmonitorfilter.h"
#include "canmonitormodel.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QTableView;
class QToolButton;

namespace db {
class DeviceConnection;
}

namespace db::widgets {

class FrameSender;

class CanMonitor : public QWidget
{
    Q_OBJECT
public:
    explicit CanMonitor(QWidget *parent = nullptr);
    ~CanMonitor() override;

    // The bus of the connection's CANopen network, with the connection's dictionary for its
    // node. nullptr, or a connection that is on no CANopen network, detaches; recorded frames
    // stay until cleared. Not owned.
    void setConnection(DeviceConnection *connection);
    // A bare bus (no dictionary). Not owned; nullptr detaches.
    void setBus(CanBus *bus);
    CanBus *bus() const { return m_model->bus(); }

    CanMonitorModel *model() const { return m_model; }
    CanMonitorFilter *filter() const { return m_filter; }
    QTableView *view() const { return m_view; }
    FrameSender *frameSender() const { return m_sender; }

    bool isPaused() const { return m_model->isPaused(); }
    bool autoscroll() const;
    void setAutoscroll(bool on);

    // The frames shown (after the filters) as a candump log; atomic. interface: the log's
    // interface token (empty: derived from the bus name, else "can0").
    Result<void> saveLog(const QString &path, const QString &interface = {}) const;

public Q_SLOTS:
    void setPaused(bool paused);
    void clear();
    void saveLogAs();

private:
    QWidget *createToolBar();
    QWidget *createFilterBar();
    void setupView();
    void applyFilter();
    void onFlushed();
    void updateStatus();

    CanMonitorModel *m_model;
    CanMonitorFilter *m_filter;
    QTableView *m_view;
    FrameSender *m_sender;
    QToolButton *m_pauseButton = nullptr;
    QCheckBox *m_autoscroll = nullptr;
    QLineEdit *m_idEdit = nullptr;
    QComboBox *m_directionBox = nullptr;
    QLineEdit *m_objectEdit = nullptr;
    QLineEdit *m_dataEdit = nullptr;
    QLineEdit *m_textEdit = nullptr;
    QLabel *m_status = nullptr;
    QMetaObject::Connection m_dictionaryWatch; // the network's descriptions -> the decoder
};

} // namespace db::widgets
