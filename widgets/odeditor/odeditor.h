#pragma once

#include "core/changelog.h"
#include "core/deviceconnection.h"

#include <QPointer>
#include <QWidget>

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QTreeView;

namespace db::widgets {

class DescriptionPrompt;
class FlowLayout;
class OdBitFieldView;
class OdEditorDelegate;
class OdEditorFilter;
class OdEditorModel;
class OdEditorPoller;

// The object-dictionary editor page: every object of the current device in a
// tree grouped by communication / manufacturer / profile, a filter by index, name or value,
// live refresh of the visible rows, in-place editing checked before anything is sent, a details
// pane with the bits of the selected word, read/write by index for objects the description does
// not know, and dragging objects out (OdEditorModel::kMimeType).
//
// After connecting it reads every readable object once (in the background, OdEditorPoller's
// limits), then refreshes only the rows on screen at the chosen period. Values from the device
// never cause a write; a write is sent only when the user commits an edit.
class OdEditor : public QWidget
{
    Q_OBJECT
public:
    explicit OdEditor(QWidget *parent = nullptr);
    ~OdEditor() override;

    // May be null; not owned. The dictionary is taken from the connection.
    void setConnection(DeviceConnection *connection);
    DeviceConnection *connection() const { return m_connection; }
    // Every write the editor sends is recorded there (null: none).
    void setChangeLog(ChangeLog *log) { m_changeLog = log; }

    // A drop-down button `title` with these actions in the editor's tool row (e.g. the
    // Parameters menu's backup, compare and store).
    void addToolActions(const QString &title, const QList<QAction *> &actions);

    OdEditorModel *model() const { return m_model; }
    OdEditorFilter *filter() const { return m_filter; }
    OdEditorPoller *poller() const { return m_poller; }
    QTreeView *view() const { return m_view; }
    OdBitFieldView *details() const { return m_details; }

    void setFilterText(const QString &text);
    // Puts the keyboard focus into the filter field, its text selected (Ctrl+F).
    void focusFilter();
    void setHex(bool hex);
    // Edits go to the device's RAM only (lost at power-off, sparing its EEPROM) instead of the
    // permanent data set; offered only for devices that have such addresses
    // (DeviceConnection::ramAddress()). Off by default.
    void setWritesToRam(bool ram);
    bool writesToRam() const;
    // One of OdEditorPoller::kPeriodsMs (0 = off); other values pick the nearest.
    void setRefreshPeriodMs(int ms);
    int refreshPeriodMs() const;
    // The status line: the last refusal, write result or device error.
    QString statusText() const;
    // The addresses of the rows currently on screen (what a refresh round reads).
    QList<ObjectAddress> visibleAddresses() const;
    // Shown instead of an empty table when the connected device has no description.
    DescriptionPrompt *descriptionPrompt() const { return m_prompt; }
    // Loads the file as the description of the current device (its node id resolves $NODEID)
    // and emits descriptionFileUsed(); a file that does not load is named in the prompt.
    bool useDescriptionFile(const QString &path);

public Q_SLOTS:
    void readAll();
    // Dialog for objects missing from the description (address + type).
    void showAccessByIndex();

Q_SIGNALS:
    // After every write the editor sent: ok, or the device's (or connection's) error.
    void writeFinished(db::ObjectAddress address, bool ok, const QString &message);
    // The user chose this file as the current device's description (e.g. to add it to the
    // description library).
    void descriptionFileUsed(const QString &path);

private:
    void onStateChanged();
    void onDictionaryChanged();
    void onWriteRequested(ObjectAddress address, const QVariant &raw);
    void onCurrentChanged();
    // Data-set columns next to the value column, with the value delegate.
    void arrangeColumns();
    void onModelDataChanged(const QModelIndex &topLeft, const QModelIndex &bottomRight);
    void showStatus(const QString &text, const QColor &color = {});
    void updateCounts();

    QPointer<DeviceConnection> m_connection;
    QPointer<ChangeLog> m_changeLog;
    QMetaObject::Connection m_stateConnection;
    QMetaObject::Connection m_dictionaryConnection;
    quint64 m_generation = 0;

    OdEditorModel *m_model;
    OdEditorFilter *m_filter;
    OdEditorPoller *m_poller;
    OdEditorDelegate *m_delegate;
    QLineEdit *m_filterEdit;
    QCheckBox *m_hex;
    QCheckBox *m_ram;
    QComboBox *m_rate;
    FlowLayout *m_tools; // wraps on a narrow window
    QTreeView *m_view;
    OdBitFieldView *m_details;
    QLabel *m_counts;
    QLabel *m_status;
    DescriptionPrompt *m_prompt;
};

} // namespace db::widgets
