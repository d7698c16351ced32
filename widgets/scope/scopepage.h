#pragma once

#include "core/objectaddress.h"
#include "core/result.h"
#include "scope/pdodiscovery.h"
#include "scope/pdosource.h"
#include "scope/pollingsource.h"
#include "scope/recorder.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <optional>

class QAbstractItemModel;
class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QMimeData;
class QPushButton;
class QSpinBox;
class QTableView;

namespace db::widgets {

class ScopeChannelModel;
class ScopeMeasurements;
class ScopePlot;

// The scope page: channels (added by address or dropped from the object-dictionary editor),
// acquisition mode and trigger, Start/Stop and status, the plot with cursors and their
// measurements, CSV/PNG/PDF export, opening a saved recording, spectrum/step analysis.
//
// Ownership: the page owns its Recorder and the PollingSource/PdoSource it makes on the
// connection given to setConnection() (never a transport). Start re-creates the sources with the
// page's channels on the current connection (so a loaded recording can be recorded again); the
// recorded data stays in the Recorder until the next Start or Open.
//
// Several devices: every connection given to setConnection() is remembered (not owned) while it
// lives. A channel belongs to the device it was added from (ChannelInfo::device, its URI) and is
// recorded from it, so that the same object of two drives can be recorded side by side; its name
// carries the device then (scopeChannelName()). Changing the current connection only changes
// where new channels come from: a running recording goes on (setConnection(nullptr) stops it).
// At Start, a channel whose device is gone (a loaded recording, a removed connection) is
// recorded from the current connection.
//
// On a CANopen connection, new channels come from host polling (SDO) or, passively, from the
// TPDOs that already carry them (the "Source" box): the page reads the node's PDO configuration
// (read-only) and samples the PDO frames; it sends nothing and never changes the NMT state.
// Objects in no TPDO can be mapped into one with "Map to TPDO…" (opt-in, after a confirmation:
// it changes the device's PDO configuration).
class ScopePage : public QWidget
{
    Q_OBJECT
public:
    // Drag and drop between widgets: UTF-8 text, one ObjectAddress::toString() per line.
    static constexpr const char *kObjectsMimeType = "application/x-drivebench-objects";
    static constexpr int kStatusHz = 4;
    static constexpr int kMeasureDelayMs = 40; // coalesces cursor drags

    explicit ScopePage(QWidget *parent = nullptr);
    ~ScopePage() override;

    void setConnection(DeviceConnection *connection);
    DeviceConnection *connection() const { return m_connection; }

    scope::Recorder *recorder() const { return m_recorder; }
    ScopePlot *plot() const { return m_plot; }
    ScopeChannelModel *channelModel() const { return m_model; }
    ScopeMeasurements *measurements() const { return m_measurements; }

    // Adds polling channels on the current connection (while not recording). rateMs < 0 takes
    // the page's rate box. Addresses already present are skipped. The error names every
    // address that could not be added and why; the others are added.
    Result<void> addChannels(const QList<ObjectAddress> &addresses, int rateMs = -1);
    bool removeChannel(int index);
    // The addresses in a drag's mime data (kObjectsMimeType), read in `format` (the device's);
    // InvalidArgument naming a bad line, or the drag's own format when it is another one (an
    // "addresses KEY" first line; none means CANopen).
    static Result<QList<ObjectAddress>>
    parseObjects(const QMimeData *mime, const AddressFormat &format = AddressFormat::canopen());

    // Where new channels come from (the "Source" box; PDO only on a CANopen connection).
    enum class ChannelSource { Polling, Pdo };
    void setChannelSource(ChannelSource source);
    ChannelSource channelSource() const;
    // PDO (passive): reads the node's TPDO configuration (read-only, asynchronous) and adds the
    // objects found in a TPDO as PDO channels; objects in no TPDO are named in the status line
    // and kept for mapToTpdo(). pdoLookupFinished() follows in every case.
    void addPdoChannels(const QList<ObjectAddress> &addresses);
    // The objects of the last PDO lookup that are in no TPDO.
    QList<ObjectAddress> unmappedObjects() const { return m_unmapped; }
    // OPT-IN, without asking (the "Map to TPDO…" button asks first): writes TPDO tpdoNumber
    // (0-based) so that it carries unmappedObjects() every eventMs (RAM only), then adds them as
    // PDO channels. pdoLookupFinished() follows.
    void mapToTpdo(int tpdoNumber, int eventMs);
    // The PDO a channel (id, of the current connection) is sampled from; nullopt for polling
    // channels.
    std::optional<scope::PdoSource::Mapping> pdoMapping(const QString &id) const;
    // What a channel of this connection is called: its product and host ("MovingCap ETH
    // 127.0.0.1"), with port and node when another remembered connection has the same.
    QString deviceName(const DeviceConnection *connection) const;

    // Trigger settings of the controls (channel -1 when no channel is chosen).
    scope::Trigger triggerSettings() const;
    void setTriggerSettings(const scope::Trigger &trigger);
    // Mode as in scope::Recorder::Mode (the combo box's index).
    void setMode(int mode);

    void setCursorsEnabled(bool enabled);
    bool cursorsEnabled() const;

    Result<void> exportCsv(const QString &fileName, bool visibleRangeOnly) const;
    // PNG or PDF by the file's suffix: the plot under a header with the device(s), the
    // recording's date and time (local) and the trigger settings (or the mode when untriggered).
    Result<void> exportImage(const QString &fileName) const;
    // The header lines of an image export.
    QStringList exportHeader() const;
    Result<void> openRecording(const QString &fileName);
    // The last problem or result shown in the status line.
    QString statusText() const;

Q_SIGNALS:
    void pdoLookupFinished(bool ok);

public Q_SLOTS:
    // Records the channels on the current connection with the controls' mode and trigger; a
    // refused start is shown in the status line.
    void start();
    void stop();
    void showAnalysis();

protected:
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    QWidget *createChannelPanel();
    QWidget *createAcquisitionPanel();
    QWidget *createToolBar();
    void updateControls();
    void updateStatus();
    void updateTriggerChannels();
    void scheduleMeasurements();
    void measure();
    void showMessage(const QString &text, bool error);
    void addFromEdit();
    // The connection's (CANopen's without one): what the address field and drops take.
    const AddressFormat &addressFormat() const;
    void removeSelected();
    void chooseColor(int row);
    void promptOpen();
    void promptExportCsv(bool visibleRangeOnly);
    void promptExportImage();
    Result<void> rebuildSource();
    // The remembered, still existing connection a channel was added from; null when none.
    DeviceConnection *connectionOf(const scope::ChannelInfo &info) const
    {
        return connectionOf(info.device);
    }
    DeviceConnection *connectionOf(const QString &device) const; // by its URI
    scope::ChannelInfo channelFor(ObjectAddress address, int rateMs) const;
    static QString pdoKey(const QString &device, const QString &id);
    void onPdoPlan(Reply *reply);
    void promptMapToTpdo();
    QString channelSourceNote(const QString &id) const;
    QWidget *createSourceRow(QWidget *parent);
    void watchPdoArrival();
    QAbstractItemModel *createTableModel();

    QPointer<DeviceConnection> m_connection;
    scope::Recorder *m_recorder;
    QList<QPointer<DeviceConnection>> m_devices; // every connection given, while it lives
    QPointer<scope::PollingSource> m_source; // new polling channels of the current connection
    QPointer<scope::PdoSource> m_pdoSource; // new PDO channels of the current connection
    QList<QPointer<scope::TraceSource>> m_otherSources; // of other connections, made at Start
    QHash<QString, scope::PdoChannelPlanEntry> m_pdoMappings; // pdoKey() -> its PDO
    QString m_triggerChoice; // the trigger channel chosen last (ScopeChannelModel::key)
    QHash<QString, QList<canopen::PdoConfig>> m_tpdos; // device URI -> its TPDOs as last read
    int m_pdoWatch = 0; // counts starts: a first-PDO check of an earlier run is ignored
    QList<ObjectAddress> m_unmapped; // objects of the last PDO lookup in no TPDO
    int m_proposedTpdo = 0; // 0-based TPDO offered by "Map to TPDO…"
    QPointer<Reply> m_pdoRequest; // lookup or TPDO write in flight
    ScopePlot *m_plot;
    ScopeChannelModel *m_model;
    ScopeMeasurements *m_measurements;
    QTableView *m_channelView = nullptr;
    QLineEdit *m_addressEdit = nullptr;
    QSpinBox *m_rateBox = nullptr;
    QPushButton *m_addButton = nullptr;
    QPushButton *m_removeButton = nullptr;
    QComboBox *m_sourceBox = nullptr;
    QLabel *m_sourceLabel = nullptr;
    QPushButton *m_mapButton = nullptr;
    QComboBox *m_modeBox = nullptr;
    QDoubleSpinBox *m_rollBox = nullptr;
    QComboBox *m_triggerChannelBox = nullptr;
    QComboBox *m_triggerKindBox = nullptr;
    QDoubleSpinBox *m_levelBox = nullptr;
    QDoubleSpinBox *m_level2Box = nullptr;
    QSpinBox *m_bitBox = nullptr;
    QDoubleSpinBox *m_preBox = nullptr;
    QDoubleSpinBox *m_postBox = nullptr;
    QPushButton *m_startButton = nullptr;
    QPushButton *m_stopButton = nullptr;
    QLabel *m_stateLabel = nullptr;
    QLabel *m_countLabel = nullptr;
    QLabel *m_messageLabel = nullptr;
    QAction *m_cursorAction = nullptr;
    QTimer m_statusTimer;
    QTimer m_measureTimer;
};

} // namespace db::widgets
