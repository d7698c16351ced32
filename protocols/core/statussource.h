#pragma once

#include "error.h"
#include "objectaddress.h"

#include <QElapsedTimer>
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
    bool fresh = false; // its last read succeeded
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
// it (acquire()/release()). Every cycle reads the status word; every other object only when a
// consumer that wants it is due, that is when its interval has passed since the cycle that last
// served it (anonymous users want polledObjects() at intervalMs(), holders their own objects at
// their own interval), so a fast consumer of four objects does not make the source read nine
// at its rate. A cycle reads its objects at once (or as one block telegram); the next starts
// effectiveIntervalMs() after the previous one finished, so a slow device is never flooded. A
// failed read keeps the old value, marked stale, with the error. updated() follows every
// finished cycle and every disconnect. Whoever needs values read after its own command (an
// axis after a control word, a procedure waiting for a state) asks refresh() for them instead
// of reading itself: the source is the connection's one reader of its status.
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
    // intervalMs (the shortest interval of all holders wins), and the status word and `extra`
    // objects read at that interval. Acquiring again replaces the holder's needs;
    // release(holder) or the holder's destruction ends them.
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
    // refresh() reads everything cycleObjects() holds; refresh(requester) the status word and
    // the objects `requester` holds the source for (only the status word for anyone else).
    quint64 refresh();
    quint64 refresh(const QObject *requester);
    // Cycles finished since the source was made (never reset, unlike cycles()).
    quint64 serial() const { return m_serial; }

    // ---- what the family shows (fixed per source) ----
    virtual QString statusWordLabel() const = 0; // "Statusword (6041h)"
    virtual QList<StatusLamp> lamps() const = 0;
    virtual QList<StatusIoRow> ioRows() const { return {}; }
    // Every object the family shows (what an anonymous user wants).
    virtual QList<ObjectAddress> polledObjects() const = 0;
    // Every object the cycles read, each at its consumers' rate: the status word,
    // polledObjects() while an anonymous user holds the source, and the holders' objects that
    // the connection's description has (a device would answer the others with errors only).
    QList<ObjectAddress> cycleObjects() const;
    // The objects the last finished cycle read (successfully or not).
    bool readInLastCycle(ObjectAddress address) const { return m_lastCycle.contains(address); }

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
    // The last read of `address` succeeded (on this connection).
    bool isFresh(ObjectAddress address) const { return m_fresh.contains(address); }
    // Objects whose last read failed, address -> error text; readError() the error itself.
    const QHash<ObjectAddress, QString> &errors() const { return m_errors; }
    Error readError(ObjectAddress address) const { return m_readErrors.value(address); }
    // Cycles finished since the connection was made (for tests and statistics).
    int cycles() const { return m_cycles; }

Q_SIGNALS:
    // After every finished poll cycle (whether every read succeeded or not) and after the
    // connection went away (everything stale).
    void updated();

protected:
    // Starts one cycle that reads dueObjects(); the subclass reports every value with
    // store()/storeError() and ends with finishCycle(). Called only while connected and held,
    // never while a cycle runs.
    virtual void poll() = 0;
    // What the running cycle reads (fixed when it starts): the status word and the objects of
    // the consumers that are due or asked for a refresh.
    const QList<ObjectAddress> &dueObjects() const { return m_due; }
    // The connection was (re)made: anything defined on the device for polling is gone.
    virtual void connectionMade() { }

    // Reads every address at once and finishes the cycle when all have answered.
    void readEach(const QList<ObjectAddress> &addresses);
    void store(ObjectAddress address, const QVariant &raw);
    void storeError(ObjectAddress address, const Error &error);
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
        QElapsedTimer served; // since the start of the last cycle that read `extra`
        bool refresh = false; // asked for values read after a refresh(holder)
    };
    // Whether a consumer with this interval, last served `served` ago, is due now.
    static bool isDue(const QElapsedTimer &served, int intervalMs);
    // Decides what the cycle that starts now reads (m_due) and marks the consumers served.
    void planCycle();
    // The status word when the family polls it.
    QList<ObjectAddress> statusWordObjects() const;
    void addKnown(QList<ObjectAddress> &to, const QList<ObjectAddress> &objects) const;
    void withdraw(const QList<QPointer<Reply>> &replies, const Error &cause);

    QPointer<DeviceConnection> m_connection;
    QTimer m_timer;
    int m_users = 0;
    QHash<const QObject *, Demand> m_holders;
    int m_intervalMs = kDefaultIntervalMs;
    bool m_busy = false;
    bool m_refresh = false; // a cycle was asked for that starts after the running one
    bool m_refreshAll = false; // ... and it reads every object (refresh())
    bool m_refreshStatusWord = false; // ... and it reads the status word
    QElapsedTimer m_usersServed; // since the last cycle that read polledObjects() for users
    QList<ObjectAddress> m_due;
    QSet<ObjectAddress> m_lastCycle; // read in the last finished cycle
    QSet<ObjectAddress> m_readThisCycle;
    int m_pending = 0;
    int m_cycles = 0;
    quint64 m_serial = 0;
    quint64 m_generation = 0;
    ObjectAddress m_statusWordAddress;
    QHash<ObjectAddress, QVariant> m_values;
    QHash<ObjectAddress, QString> m_errors;
    QHash<ObjectAddress, Error> m_readErrors;
    QSet<ObjectAddress> m_fresh;
};

} // namespace db
