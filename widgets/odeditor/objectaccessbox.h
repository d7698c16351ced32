#pragma once

#include "core/changelog.h"
#include "core/deviceconnection.h"

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace db::widgets {

// Reads and writes one object by address ("6041:0"). Shows the dictionary's name, type, access
// and unit; objects the description does not know can still be accessed (read as integer, or
// written with the type the user picks). Input is checked with ObjectDef::parseText() before
// anything is sent; the result or the error (local or the device's) appears next to the value.
// Never shows a message box.
class ObjectAccessBox : public QWidget
{
    Q_OBJECT
public:
    explicit ObjectAccessBox(QWidget *parent = nullptr);

    // May be null; not owned.
    void setConnection(DeviceConnection *connection);
    DeviceConnection *connection() const { return m_connection; }
    // Every write is recorded there (null: none).
    void setChangeLog(ChangeLog *log) { m_changeLog = log; }

    QString addressText() const;
    void setAddressText(const QString &text);
    QString valueText() const;
    void setValueText(const QString &text);
    bool isHex() const;
    void setHex(bool hex);

    bool isBusy() const { return m_busy; }
    // The last outcome ("read 0x0427", "device error: ..."), as shown next to the value.
    QString resultText() const;
    // The metadata used for the current address: the dictionary's, or one made from the type
    // picked for an unknown object. Null when the address does not parse.
    std::optional<ObjectDef> currentDefinition() const;

public Q_SLOTS:
    void read();
    void write();

Q_SIGNALS:
    // After every read or write attempt, including those refused locally.
    void finished(bool ok);

private:
    // The connection's (CANopen's without one): what the address field takes and shows.
    const AddressFormat &addressFormat() const;
    void updateInfo();
    void updateActions();
    void setBusy(bool busy);
    void showResult(bool ok, const QString &text);
    void showValue();
    void onReplyFinished(class Reply *reply, bool isRead, quint64 generation);

    QPointer<DeviceConnection> m_connection;
    QPointer<ChangeLog> m_changeLog;
    QList<QMetaObject::Connection> m_connectionSignals;
    quint64 m_generation = 0;
    bool m_busy = false;
    QVariant m_lastRaw;

    QLineEdit *m_address;
    QComboBox *m_type;
    QLabel *m_info;
    QLineEdit *m_value;
    QCheckBox *m_hex;
    QPushButton *m_readButton;
    QPushButton *m_writeButton;
    QProgressBar *m_progress;
    QLabel *m_result;
};

} // namespace db::widgets
