#pragma once

#include "objectaddress.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QStringList>
#include <QTimer>
#include <QVariant>

namespace db {

class DeviceConnection;
class Reply;

// One value a status source shows: where it comes from and its last reading.
struct StatusValue
{
    QString key; // stable, for widgets and tests: "position", "current", "frequency", ...
    QString label; // for people, with the object's address: "Position (6064h)"
    ObjectAddress address;
    QVariant raw; // the last good raw value; kept (stale) when a later read fails
    QString text; // raw as the description shows it ("12345 units", "10.2 A"), "—" before
    bool fresh = false; // read successfully in the last cycle
    QString error; // why the last read failed
};

// A lamp for one bit of the status word.
struct StatusLamp
{
    enum class Kind { Ok, Info, Warning, Error };
    quint32 mask = 0;
    QString name; // translated
    Kind kind = Kind::Info;
};

// A row of digital inputs or outputs: bit firstBit + i of the value at `address` is item i.
struct StatusIoRow
{
    QString label; // "Inputs (60FDh):"
    QString prefix; // "IN", "OUT"
    ObjectAddress address;
    int firstBit = 0;
    int count = 0;
};

// The live status of one drive, whatever its family: its state, status word, mode, current
// fault, warnings and actual values. A device family provides one per connection
// (DeviceConnection::statusSource()); everybody who shows the drive's status shares it, so the
// device is polled once however many views are open.
//
// Polling contract: polling runs while the connection is Connected and at least one user holds
// it (acquire()/release()). One cycle reads what the family needs and what the holders asked
// for (every object at once, or one block telegram); the next cycle starts intervalMs() after
// the previous one finished (the shortest interval a holder asked for), so a slow device is
// never flooded. A failed read keeps the old value, marked stale, with the error. updated()
// follows every finished cycle and every disconnect. Whoever needs values read after its own
// command (an axis after a control word) asks refresh() for them instead of reading itself.
class StatusSource : public QObject
{
    Q_OBJECT
public:
    // The drive's power state, named as CiA 402 names it; inverter state machines built on the
    // same pattern (e.g. the ACTIVE Cube's 411) map onto it.
    enum class State {
        Unknown,
        NotReadyToSwitchOn,
        SwitchOnDisabled,
        ReadyToSwitchOn,
        SwitchedOn,
        OperationEnabled,
        QuickStopActive,
        FaultReactionActive,
        Fault,
    };
    Q_ENUM(State)

    static constexpr int kDefaultIntervalMs = 200;

    // The connection is not owned; the source normally is its child (setStatusSource()).
    explicit StatusSource(DeviceConnection *connection, QObject *parent = nullptr);
    ~StatusSource() override;

    DeviceConnection *connection() const;

    // ---- polling ----
    // Users that want fresh values hold the source; it polls while anyone holds it.
    void acquire();
    void release();
    // A holder with needs of its own (an axis following its motion): cycles at least every
    // intervalMs (the shortest interval of all holders wins), and `extra` objects read in every
    // cycle besides polledObjects(). Acquiring again replaces the holder's needs; release(holder)
    // or the holder's destruction ends them.
    void acquire(const QObject *holder, int intervalMs, const QList<ObjectAddress> &extra = {});
    void release(const QObject *holder);
    int users() const { return m_users + int(m_holders.size()); }
    // The interval set for anonymous users (setIntervalMs); effectiveIntervalMs() is the one in
    // use, holders' shorter ones included.
    int intervalMs() const { return m_intervalMs; }
    int effectiveIntervalMs() const;
    void setIntervalMs(int ms);
    // A cycle is scheduled or in flight.
    bool isPolling() const { return m_timer.isActive() || m_busy; }
    // Asks for values read after now, held or not: a cycle starts at once when none runs, or
    // right after the running one (whose reads may predate the caller's last write). Returns
    // the serial() that cycle will have: once serial() reaches it, updated() has brought
    // values read after the call. Nothing happens while disconnected.
    quint64 refresh();
    // Cycles finished since the source was made (never reset, unlike cycles()).
    quint64 serial() const { return m_serial; }

    // ---- what the family shows (fixed per source) ----
    virtual QString statusWordLabel() const = 0; // "Statusword (6041h)"
    virtual QList<StatusLamp> lamps() const = 0;
    virtual QList<StatusIoRow> ioRows() const { return {}; }
    // Every object the family reads in one cycle.
    virtual QList<ObjectAddress> polledObjects() const = 0;
    // What the next cycle reads: polledObjects() and the holders' extra objects that the
    // connection's description has (a device would answer the others with errors only).
    QList<ObjectAddress> cycleObjects() const;

    // ---- the data ----
    State state() const;
    static QString stateText(State state); // translated "Operation enabled"
    std::optional<quint32> statusWord() const;
    StatusValue statusWordValue() const;
    // Operation mode as text ("Profile position (1)"); key empty when the family shows none.
    virtual StatusValue mode() const { return {}; }
    virtual QList<StatusValue> actualValues() const = 0;
    // The current (or last) fault: text is the code as the drive's documentation writes it
    // ("0x3221 ERROR_UNDER_VOLT", "F2714"); faultText() its meaning ("No error" when none).
    virtual StatusValue fault() const = 0;
    virtual QString faultText() const = 0;
    virtual bool faultActive() const = 0;
    // A fault/warning register shown beside the fault (1002h), key empty when none.
    virtual StatusValue faultRegister() const { return {}; }
    // Active error bits and warnings, one text each.
    virtual QStringList errorBits() const { return {}; }
    virtual QStringList warnings() const = 0;
    // What the drive does when the link stops, for people; empty when the family says nothing.
    virtual QString linkLossText() const { return {}; }

    // The last raw value read at an address (invalid before the first good read).
    QVariant value(ObjectAddress address) const { return m_values.value(address); }
    bool isFresh(ObjectAddress address) const { return m_fresh.contains(address); }
    // Failed reads of the last cycle, address -> error text.
    const QHash<ObjectAddress, QString> &errors() const { return m_errors; }
    // Cycles finished since the connection was made (for tests and statistics).
    int cycles() const { return m_cycles; }

Q_SIGNALS:
    // After every finished poll cycle (whether every read succeeded or not) and after the
    // connection went away (everything stale).
    void updated();

protected:
    // Starts one cycle; the subclass reports every value with store()/storeError() and ends
    // with finishCycle(). Called only while connected and held, never while a cycle runs.
    virtual void poll() = 0;
    // The connection was (re)made: anything defined on the device for polling is gone.
    virtual void connectionMade() { }

    // Reads every address at once and finishes the cycle when all have answered.
    void readEach(const QList<ObjectAddress> &addresses);
    void store(ObjectAddress address, const QVariant &raw);
    void storeError(ObjectAddress address, const QString &error);
    void finishCycle();
    // Guards replies of an earlier connection or cycle: compare with generation().
    quint64 generation() const { return m_generation; }

    // Builds a StatusValue for `address` from what was read, its text from the dictionary.
    StatusValue makeValue(const QString &key, const QString &label, ObjectAddress address) const;
    void setStatusWordAddress(ObjectAddress address) { m_statusWordAddress = address; }
    // From a DS402-style status word (bits 0-3, 5, 6: mask 0x006F).
    static State decodeState(quint32 statusWord);

private:
    void onStateChanged();
    void schedule(int delayMs);
    void start();
    bool wanted() const { return m_users > 0 || !m_holders.isEmpty() || m_refresh; }

    struct Demand
    {
        int intervalMs = kDefaultIntervalMs;
        QList<ObjectAddress> extra;
        QMetaObject::Connection destroyed;
    };

    QPointer<DeviceConnection> m_connection;
    QTimer m_timer;
    int m_users = 0;
    QHash<const QObject *, Demand> m_holders;
    int m_intervalMs = kDefaultIntervalMs;
    bool m_busy = false;
    bool m_refresh = false; // a cycle was asked for that starts after the running one
    int m_pending = 0;
    int m_cycles = 0;
    quint64 m_serial = 0;
    quint64 m_generation = 0;
    ObjectAddress m_statusWordAddress;
    QHash<ObjectAddress, QVariant> m_values;
    QHash<ObjectAddress, QString> m_errors;
    QSet<ObjectAddress> m_fresh;
};

} // namespace db
