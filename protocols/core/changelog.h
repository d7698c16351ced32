#pragma once

#include "error.h"
#include "objectaddress.h"

#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>

namespace db {

class DeviceConnection;
class Reply;

// What the user changed on the devices during a session: every write, restore, permanent store,
// enable, motion command, NMT command and CAN frame sent by hand, with time, device, object, old
// and new value and the outcome. Views show it; saveCsv() keeps it. Entries are added when the
// action starts and completed when its outcome is known, so an action that never finishes stays
// visibly pending.
//
// A successful write is marked "not stored" until the same device stores its parameters
// permanently (markStored()): it is lost at the next power cycle until then. Writes to a
// device's working memory only are never marked stored.
class ChangeLog : public QObject
{
    Q_OBJECT
public:
    enum class Kind { Write, Restore, Store, Enable, Disable, Motion, Nmt, Reset, Frame };
    Q_ENUM(Kind)
    enum class Outcome { Pending, Ok, Failed, Aborted };
    Q_ENUM(Outcome)

    struct Entry
    {
        int id = 0;
        QDateTime time;
        QString device; // the connection's URI, or the network for NMT
        Kind kind = Kind::Write;
        QString object; // "6083:0 Profile acceleration", "Jog +", "node 5"
        QString oldValue; // empty when unknown
        QString newValue;
        Outcome outcome = Outcome::Pending;
        QString message; // the device's refusal or the error; empty when ok
        bool storable = false; // a write that a permanent store would keep
        bool stored = false;
        bool workingMemoryOnly = false; // written where a permanent store does not reach
    };

    // Older entries are dropped beyond this (a session's user actions are far fewer).
    static constexpr int kMaxEntries = 100000;

    explicit ChangeLog(QObject *parent = nullptr);

    const QList<Entry> &entries() const { return m_entries; }
    int count() const { return int(m_entries.size()); }
    // The entry with this id, or null when it was dropped or never existed.
    const Entry *find(int id) const;

    // Adds the entry (its time is now unless set) and returns its id.
    int add(Entry entry);
    // Completes a pending entry; no effect on unknown ids or finished entries.
    void complete(int id, const Error &error);
    // Completes a pending entry with this outcome and message.
    void complete(int id, Outcome outcome, const QString &message);
    // Adds the entry and completes it when the reply finishes (with the reply's error).
    int track(Entry entry, Reply *reply);
    // Every successful storable write to `device` so far is kept permanently now.
    void markStored(const QString &device);
    // Writes that succeeded and are not stored, per device.
    int unstoredCount(const QString &device) const;
    void clear();

    // CSV with a header line: time (ISO 8601, milliseconds, local offset), device, action, object,
    // old value, new value, result, message, stored (yes, no, RAM only, or empty
    // where it does not apply). Written atomically: a failure leaves an
    // existing file as it was and names the cause.
    Error saveCsv(const QString &path) const;
    QString toCsv() const;

    // A write of `address` on `connection`: the device, "ADDRESS Name" in the connection's
    // address format, storable when the device can store its parameters permanently.
    static Entry writeEntry(const DeviceConnection &connection, ObjectAddress address,
                            const QString &oldValue, const QString &newValue,
                            bool workingMemoryOnly = false);

    static QString kindName(Kind kind); // translated
    static QString outcomeName(Outcome outcome); // translated
    // "yes", "no" (a write a permanent store would keep, not stored yet), "RAM only", or empty.
    static QString storedText(const Entry &entry);
    // One line for the log: "DEVICE: write 6083:0 Name 1000 → 2000: ok".
    static QString summary(const Entry &entry);

Q_SIGNALS:
    void entryAdded(int index);
    void entryChanged(int index);
    void entriesRemoved(int first, int count); // dropped at the front, or cleared
    void cleared();

private:
    int indexOf(int id) const;

    QList<Entry> m_entries;
    int m_nextId = 1;
};

} // namespace db
