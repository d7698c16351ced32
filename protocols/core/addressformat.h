#pragma once

#include "objectaddress.h"
#include "result.h"

#include <QString>

namespace db {

// How people write the address of an object for one family of devices. An ObjectAddress is
// two numbers (index + sub-index, or parameter number + data set); the format decides the
// radix, the separator and the names used in messages. Connections, protocol descriptions and
// the CLI ask the format instead of assuming hexadecimal CANopen addresses.
class AddressFormat
{
public:
    virtual ~AddressFormat() = default;

    // Stable key: "canopen" (hex INDEX:SUB) or "parameter" (decimal NUMBER:DATASET).
    virtual QString key() const = 0;
    virtual Result<ObjectAddress> parse(const QString &text) const = 0;
    // The canonical form, accepted by parse().
    virtual QString format(ObjectAddress address) const = 0;
    // For help texts and error messages: "6041:0", "372:2".
    virtual QString example() const = 0;
    // What the two parts are called: "index"/"sub-index", "parameter"/"data set".
    virtual QString indexName() const = 0;
    virtual QString subName() const = 0;
    // The index (parameter number) alone, as format() writes it: "6041", "372".
    QString formatIndex(quint16 index) const;

    // Hexadecimal INDEX:SUB as in CiA 301 ("6041:0"; see ObjectAddress::parse for the forms
    // accepted).
    static const AddressFormat &canopen();
    // Decimal NUMBER:DATASET ("372:2"; "12" is data set 0), as inverter parameter lists write
    // them.
    static const AddressFormat &parameter();
    // By key; nullptr when unknown.
    static const AddressFormat *byKey(const QString &key);
};

} // namespace db
