#include "groupreader.h"

#include "deviceconnection.h"

namespace db {

GroupReader *GroupReader::of(const DeviceConnection *connection)
{
    return connection ? connection->findChild<GroupReader *>(QString(), Qt::FindDirectChildrenOnly)
                      : nullptr;
}

} // namespace db
