#pragma once

// ApplicationProcess parameters of a CiA 311 XDD (xddloader.cpp), referenced by objects through
// uniqueIDRef.
#include "core/datatype.h"

#include <QMap>
#include <QXmlStreamReader>

#include <optional>

namespace db::xdd {

// One ApplicationProcess <parameter>, referenced by objects through uniqueIDRef.
struct Parameter
{
    QString uniqueId;
    QString access; // read, write, readWrite, readWriteInput, readWriteOutput, const, noAccess
    QString label;
    QString description;
    QString typeName; // IEC 61131 name of the type element (UDINT, ...)
    QString defaultValue;
    QString actualValue;
    QString minValue;
    QString maxValue;
    QMap<QString, QString> allowed; // value -> label (the English one when there is one)
    QMap<QString, QMap<QString, QString>> allowedLocal = {}; // value -> (language -> label)
};

// The basic type of an IEC 61131 type element (UDINT -> UNSIGNED32, ...), CiA 311 table 5.
std::optional<DataType> typeFromIecName(const QString &name);

// Reads the <parameter> the reader stands on (its StartElement) up to its EndElement.
Parameter readParameter(QXmlStreamReader &xml);

} // namespace db::xdd
