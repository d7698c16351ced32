#pragma once

#include "core/deviceconnection.h"
#include "core/statussource.h"

#include <QPointer>
#include <QWidget>

class QFormLayout;
class QGroupBox;
class QLayout;
class QLabel;

namespace db::widgets {

class Lamp;

// The live status of a drive of any family, as its connection's StatusSource reads it: the
// state as a coloured badge, the status word and its bits, the mode, actual values, the current
// fault with its text, warnings, digital I/O where the family has them, and what the drive does
// when the link stops. A connection without a source gets the CiA 402 one.
//
// The panel holds the source (it polls) only while it is visible; several views of one
// connection share one poller. Failed reads leave the old value greyed out (stale) with the error
// as tool tip; nothing pops up.
class DriveStatusPanel : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kDefaultPollIntervalMs = StatusSource::kDefaultIntervalMs;

    explicit DriveStatusPanel(QWidget *parent = nullptr);
    ~DriveStatusPanel() override;

    // May be null. The panel does not own the connection and copes with its destruction.
    void setConnection(DeviceConnection *connection);
    DeviceConnection *connection() const { return m_connection; }
    StatusSource *source() const { return m_source; }

    int pollInterval() const { return m_intervalMs; }
    void setPollInterval(int ms);
    bool isPolling() const { return m_source && m_held && m_source->isPolling(); }

    // The objects a CiA 402 drive's cycle reads: 6041h, 6061h, 6064h, 606Ch, 6078h, 1002h,
    // 603Fh, 60FDh, 60FEh.1.
    static QList<ObjectAddress> polledObjects();
    // The last raw value read (invalid before the first successful read).
    QVariant value(ObjectAddress address) const
    {
        return m_source ? m_source->value(address) : QVariant();
    }
    bool isStale(ObjectAddress address) const { return !m_source || !m_source->isFresh(address); }
    // A line under the state about the motion command model (the Motion dock's ErrorStop and
    // how to leave it); hidden when empty.
    void setMotionNote(const QString &note);
    QString motionNote() const;

Q_SIGNALS:
    // After every completed poll cycle, whether all reads succeeded or not.
    void cycleFinished();

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void buildUi();
    void buildFamilyUi();
    void hold(bool on);
    void onUpdated();
    void onStateChanged();
    void render();
    void renderState();
    void renderValues();
    void renderFaults();
    void renderIo();
    void renderFooter();

    QPointer<DeviceConnection> m_connection;
    QPointer<StatusSource> m_source;
    QList<QMetaObject::Connection> m_signals;
    int m_intervalMs = kDefaultPollIntervalMs;
    bool m_held = false;

    QLabel *m_stateLabel = nullptr;
    QLabel *m_statusWordName = nullptr;
    QLabel *m_statuswordLabel = nullptr;
    QLabel *m_modeName = nullptr;
    QLabel *m_modeLabel = nullptr;
    QLayout *m_bitRow = nullptr; // a FlowLayout: wraps on a narrow page
    QList<Lamp *> m_bitLamps;
    QGroupBox *m_valuesBox = nullptr;
    QFormLayout *m_valuesForm = nullptr;
    QList<QLabel *> m_valueLabels;
    QGroupBox *m_ioBox = nullptr;
    QList<QList<Lamp *>> m_ioLamps;
    QGroupBox *m_faultBox = nullptr;
    QLabel *m_registerName = nullptr;
    QLabel *m_registerLabel = nullptr;
    QLabel *m_registerBitsLabel = nullptr;
    QLabel *m_warningBitsLabel = nullptr;
    QLabel *m_lastErrorName = nullptr;
    QLabel *m_lastErrorLabel = nullptr;
    QLabel *m_lastErrorText = nullptr;
    QLabel *m_linkLossLabel = nullptr;
    QLabel *m_footer = nullptr;
    QLabel *m_motionNote = nullptr;
};

} // namespace db::widgets
