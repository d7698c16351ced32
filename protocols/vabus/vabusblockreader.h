#pragma once

// The one owner of the block definition (parameter 17) of a VABus connection: everybody who
// reads several word/double-word parameters often joins it, and the block holds the union of
// what they asked for, as far as 64 characters allow (see GroupReader for the contract).
//
// The definition is volatile on the inverter (lost at reset) and written to data set 0. It is
// written again before the next block read when the group changed, after every reconnect, after
// the inverter refused a block read (it was reset and lost the definition) and after anybody
// else wrote parameter 17 through the connection while nobody used the block. While the block is
// in use, the connection refuses writes to 17 and 18 (see VabusConnection), so nobody can
// silently make the users decode the wrong parameters.

#include "core/error.h"
#include "core/groupreader.h"
#include "vabusblock.h"

#include <QPointer>

#include <memory>

namespace db::vabus {

class VabusConnection;

class BlockReader : public GroupReader
{
    Q_OBJECT
public:
    // A child of the connection; its client does the telegrams.
    explicit BlockReader(VabusConnection *connection);

    QList<ObjectAddress> join(const QObject *user, const QList<ObjectAddress> &objects) override;
    void leave(const QObject *user) override;
    QList<ObjectAddress> heldFor(const QObject *user) const override;
    Reply *read(const QObject *user) override;
    bool usable() const override { return m_usable; }
    int definitions() const override { return m_definitions; }
    bool inUse() const override;

    // What the block holds for everybody, in the order of the definition.
    QList<BlockItem> items() const { return m_items; }
    // The definition on the device may differ from ours: write it before the next read.
    void forgetDefinition() { m_written.reset(); }

private:
    struct User
    {
        const QObject *user = nullptr;
        QList<ObjectAddress> held;
        QMetaObject::Connection destroyed;
    };
    // A definition as queued for writing; the reads queued after it decode with its items.
    struct Definition
    {
        QByteArray text;
        QList<BlockItem> items;
        bool done = false;
        Error error; // set when the inverter refused it
    };

    void rebuild();
    void onConnectionState();
    qsizetype indexOf(const QObject *user) const;

    VabusConnection *m_connection = nullptr;
    QList<User> m_users; // in the order they joined
    QList<BlockItem> m_items;
    std::shared_ptr<Definition> m_written; // the last definition queued; null = unknown
    bool m_usable = true;
    int m_failures = 0;
    int m_definitions = 0;
};

} // namespace db::vabus
