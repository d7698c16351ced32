#pragma once

#include "objectaddress.h"

#include <QList>
#include <QObject>

namespace db {

class DeviceConnection;
class Reply;

// Several objects of one device read in one exchange, where the protocol has such a thing (the
// VABus block: one definition on the device, parameter 17, read with 19). The device holds one
// such group, so the connection owns the reader and everybody who reads often (the status
// source, the scope's host polling) joins it instead of defining a group of its own.
//
// Contract:
// - join() replaces what a user reads in the group and returns those of its objects the group
//   holds for it: objects other users hold keep their place, an object another user holds
//   already costs nothing, and the rest is held while it fits. The user reads what is not held
//   itself. leave() or the user's destruction frees its place.
// - read() reads the whole group in one exchange and gives the user its values: the reply's
//   value is a QVariantList of raw values, one per object of heldFor(user) at the time of the
//   call, in that order. The reader writes the group's definition to the device first whenever
//   it may differ from what the device has (first use, a change of the group, a new connection,
//   the device lost it), so two users can never read under a definition they did not make.
// - nullptr from read(): the group cannot be read (nothing held for the user, or the device
//   refused the definition kMaxFailures times in a row on this connection): read one by one.
class GroupReader : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMaxFailures = 3;

    using QObject::QObject;

    // The connection's reader, or nullptr when its protocol reads every object on its own.
    static GroupReader *of(const DeviceConnection *connection);

    virtual QList<ObjectAddress> join(const QObject *user, const QList<ObjectAddress> &objects) = 0;
    virtual void leave(const QObject *user) = 0;
    // Empty while the group cannot be read (see usable()).
    virtual QList<ObjectAddress> heldFor(const QObject *user) const = 0;
    virtual Reply *read(const QObject *user) = 0;
    // False after the device refused the definition kMaxFailures times on this connection.
    virtual bool usable() const = 0;
    // Definitions written to the device since the reader was made (statistics and tests).
    virtual int definitions() const = 0;
    // Someone holds objects in the group.
    virtual bool inUse() const = 0;
};

} // namespace db
