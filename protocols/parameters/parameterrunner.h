#pragma once

#include "core/deviceconnection.h"
#include "parameterset.h"

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QStringList>

#include <memory>
#include <vector>

namespace db {

// Backup and restore of parameter sets through any DeviceConnection (ARCHITECTURE.md habit 5:
// small enum state machines on the event loop; nothing blocks). The connection must outlive the
// runner or the run fails with Error::Kind::Disconnected; the runner never opens or closes it.

// One object a backup could not read, and why.
struct BackupFailure
{
    ObjectAddress address;
    QString name; // from the description; empty when it does not know the object
    Error error;
    const AddressFormat *addressFormat = &AddressFormat::canopen(); // the device's; never null

    // "6084:0 Profile deceleration: malformed answer: ...", one line (control characters as
    // \xNN), for logs, stderr and the comment lines of a partial file.
    QString text() const;
};

// Reads objects into a ParameterSet.
//
//   Idle --start()--> Reading --(all done)--> Finished
//                       |  read fails for one object -> failure recorded, object skipped
//                       |  connection lost / not connected / 2 timeouts in a row
//                       |      -> Finished (error; the unread objects are failures too)
//                       +--cancel()--> Finished (Error::Kind::Cancelled)
//
// finished() fires exactly once per start(): from the event loop, or inside cancel() (never
// inside start()). A timeout skips one object like a device error; two in a row end the backup.
// An answer that breaks the protocol or does not fit the object's type is a failure of kind
// Malformed, whatever the layer that noticed it.
class ParameterBackup : public QObject
{
    Q_OBJECT
public:
    enum class Scope {
        Storable, // every storable, readable object of the connection's dictionary (default)
        Readable, // every readable object (the CLI's dump); objects the connection cannot
                  // carry (Error::Kind::NotSupported, e.g. strings over RefGo) are skipped()
    };
    Q_ENUM(Scope)

    static constexpr int kDefaultPipelineDepth = 1; // requests in flight at a time

    explicit ParameterBackup(DeviceConnection *connection, QObject *parent = nullptr);
    ~ParameterBackup() override;

    void setScope(Scope scope) { m_scope = scope; }
    // Reads exactly these addresses instead of the scope (objects the dictionary does not know
    // are read too and typed as returned).
    void setAddresses(const QList<ObjectAddress> &addresses) { m_explicit = addresses; }
    // 1..8 requests in flight; the protocol engines queue them, so >1 only hides latency.
    void setPipelineDepth(int depth);

    // Ignored while running.
    void start();
    // Stops at once; finished() is emitted inside cancel() with Error::Kind::Cancelled, no set.
    void cancel();
    bool isRunning() const { return m_state == State::Reading; }

    // After finished(): the complete set, or why there is none. Never a partial set: any
    // failure (an object, the identity) makes it an error whose kind is the most common
    // cause among the failures (the first on a tie), e.g. "3 of 203 objects could not be read
    // (first: ...)"; so does a run that read no object at all, and a run that stopped (error()).
    // Identity: the dictionary's, with vendor id and product code as the device reports them in
    // 1018h.1/.2 (read first, when the description has them); source = the connection's URI.
    Result<ParameterSet> result() const;
    // After finished(): every object that was read, whatever else failed (empty after a
    // cancel). vendorIdKnown / productCodeKnown are false where 1018h could not be read.
    ParameterSet partialSet() const { return m_set; }
    // The error that stopped the run before its end (connection lost, Cancelled); None when
    // every object was tried.
    Error error() const { return m_error; }
    // Every object that could not be read, in the order they were asked for; after a stop
    // also those never asked for (with the stopping error).
    QList<BackupFailure> failures() const { return m_failures; }
    // Scope::Readable: the objects the connection cannot carry; neither read nor failed.
    QList<BackupFailure> skipped() const { return m_skipped; }
    int objectCount() const { return int(m_todo.size()); } // objects to read, 1018h included
    // failures() as text lines (BackupFailure::text()).
    QStringList warnings() const;
    QList<ObjectAddress> failedAddresses() const;

Q_SIGNALS:
    void progress(int done, int total);
    void finished();

private:
    enum class State { Idle, Reading, Finished };

    void issueNext();
    void onReply(Reply *reply);
    void fail(ObjectAddress address, const Error &error);
    void finish(const Error &error);

    QPointer<DeviceConnection> m_connection;
    State m_state = State::Idle;
    Scope m_scope = Scope::Storable;
    QList<ObjectAddress> m_explicit;
    int m_depth = kDefaultPipelineDepth;
    QList<ObjectAddress> m_todo;
    int m_next = 0;
    int m_done = 0;
    QList<QPointer<Reply>> m_inFlight;
    ParameterSet m_set;
    Error m_error;
    QList<BackupFailure> m_failures;
    QList<BackupFailure> m_skipped;
    QSet<ObjectAddress> m_identityOnly; // 1018h reads that fill the identity, not the set
    int m_timeoutsInRow = 0;
};

// ---- Restore ----

enum class RestoreOutcome {
    Verified, // written and read back equal
    Written, // written, not read back (verification off, write-only object, cancelled)
    Failed, // the device refused the write (reason holds its error text)
    Mismatch, // written, but the read-back value differs (readBack holds it) or failed
    Skipped, // not attempted: read-only, unknown object, cancelled, after a fatal error
};

QString restoreOutcomeName(RestoreOutcome outcome); // "verified", "written", ...

struct RestoreRow
{
    ObjectAddress address;
    QString name;
    DataType type = DataType::Unsigned32;
    QVariant value; // the set's value
    QVariant readBack; // valid after a read-back
    RestoreOutcome outcome = RestoreOutcome::Skipped;
    QString reason; // device error, mismatch or skip reason; empty when Verified
};

struct RestoreReport
{
    QList<RestoreRow> rows; // selected rows, in the order they were (or would be) written
    bool storeRequested = false;
    bool stored = false; // 1010h "save" was written successfully
    QString storeReason; // why not stored (error text, or "not stored: 2 rows failed")
    Error error; // fatal error that stopped the run (connection lost, Cancelled); else None
    QStringList notes; // e.g. "PDO 1400h left disabled (COB-ID bit 31 set)"
    const AddressFormat *addressFormat = &AddressFormat::canopen(); // the device's; never null

    int count(RestoreOutcome outcome) const;
    // At least one row, every row Verified or Written, no fatal error, and the store done when
    // requested.
    bool succeeded() const;
    // Multi-line text: counts, then which rows were written, failed (with reason), mismatched
    // and skipped (by address and name), then the store result and notes.
    QString summary() const;
};

// Writes the selected rows of a set, in a safe order, verifying each.
//
// Order (CiA 301 7.5.2.35-38): for each RPDO/TPDO whose communication (1400h-15FFh,
// 1800h-19FFh) or mapping (1600h-17FFh, 1A00h-1BFFh) rows are selected:
//   COB-ID (sub 1) := current | bit 31 (disable) -> other communication subs -> mapping sub 0 := 0
//   -> mapping entries -> mapping sub 0 := n -> COB-ID := set value (or the previous one).
// All other rows in address order. The PDO steps run before the other rows.
// Rules: read-only/const rows and rows the connection's dictionary does not know are Skipped;
// write-only rows are Written without read-back. A failed row does not stop the run; a
// connection loss or cancel() does (rows not yet written are Skipped). A PDO the runner had
// disabled when it stopped is listed in the report's notes.
// Store (1010h sub 1 = "save") runs only when requested and every row succeeded. A run with no
// row (an empty set, or a selection none of whose addresses is in the set) writes nothing,
// never stores, and ends with Error::Kind::InvalidArgument.
//
//   Idle --start()--> Writing <-> Verifying --> Storing --> Finished
class ParameterRestore : public QObject
{
    Q_OBJECT
public:
    explicit ParameterRestore(DeviceConnection *connection, QObject *parent = nullptr);
    ~ParameterRestore() override;

    void setParameterSet(const ParameterSet &set) { m_set = set; }
    // Rows to write; empty = every row of the set. Addresses not in the set are ignored.
    void setSelection(const QList<ObjectAddress> &selection) { m_selection = selection; }
    void setVerify(bool verify) { m_verify = verify; }
    void setStoreAfterwards(bool store) { m_store = store; }

    // Ignored while running. finished() fires exactly once per start(), from the event loop.
    void start();
    // Takes effect after the request in flight; the report marks the rest Skipped.
    void cancel();
    bool isRunning() const { return m_state != State::Idle && m_state != State::Finished; }

    // Complete after finished(); empty before start().
    const RestoreReport &report() const { return m_report; }

Q_SIGNALS:
    // Counts steps: the rows plus the PDO helper steps (disable, clear mapping, re-enable).
    void progress(int done, int total);
    void finished();

private:
    enum class State { Idle, Writing, Verifying, Storing, Finished };
    struct Step;

    void plan();
    void runNext();
    void advance();
    QString blockReason(const Step &step) const;
    void onWriteDone(Reply *reply);
    void onReadBackDone(Reply *reply);
    void store();
    void onStoreDone(Reply *reply);
    void stopWithError(const Error &error);
    void finish();
    void track(Reply *reply, void (ParameterRestore::*handler)(Reply *));

    QPointer<DeviceConnection> m_connection;
    State m_state = State::Idle;
    ParameterSet m_set;
    QList<ObjectAddress> m_selection;
    bool m_verify = true;
    bool m_store = false;
    bool m_cancelRequested = false;
    int m_timeoutsInRow = 0;
    std::unique_ptr<std::vector<Step>> m_steps; // Step is private to the .cpp
    int m_stepIndex = 0;
    QPointer<Reply> m_inFlight;
    QHash<ObjectAddress, QVariant> m_current; // values read before changing a PDO
    QHash<quint16, QString> m_groupBlocked; // PDO comm index -> why its steps are not run
    QHash<quint16, QString> m_mappingBlocked; // ... why its mapping steps are not run
    QSet<quint16> m_disabled; // PDOs this run disabled and has not re-enabled yet
    RestoreReport m_report;
};

} // namespace db
