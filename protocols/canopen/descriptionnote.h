#pragma once
// Why a connection has no description, for the command line's note after a read or write by
// index: CANopen connections say which identity found no match; others have nothing to say.
#include "canopenconnection.h"

namespace db::canopen {

inline QString descriptionNoteOf(const DeviceConnection *connection)
{
    const auto *c = qobject_cast<const CanopenConnection *>(connection);
    return c ? c->descriptionNote() : QString();
}

} // namespace db::canopen
