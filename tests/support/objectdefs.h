#pragma once
// A one-line object definition for test dictionaries (name "object INDEX:SUB").
#include "core/objectdef.h"

#include <QVariant>

namespace db::test {

inline ObjectDef objectDef(quint16 index, quint8 sub, DataType type, Access access,
                           QVariant value = {})
{
    ObjectDef d;
    d.address = { index, sub };
    d.name = QStringLiteral("object %1").arg(d.address.toString());
    d.type = type;
    d.access = access;
    d.defaultValue = value;
    return d;
}

// The same with the name a test checks, and the name of the object a sub-index belongs to.
inline ObjectDef namedObjectDef(quint16 index, quint8 sub, DataType type, Access access,
                                const QString &name, const QString &objectName = {})
{
    ObjectDef d = objectDef(index, sub, type, access);
    d.name = name;
    d.objectName = objectName;
    return d;
}

} // namespace db::test
