#pragma once

#include "objectdef.h"

#include <QMap>

#include <optional>

namespace db {

// Who the description is for and where it came from.
struct DeviceIdentity
{
    QString vendorName;
    quint32 vendorId = 0;
    QString productName;
    quint32 productCode = 0;
    QString revision;
    QString descriptionFile; // path or resource the dictionary was loaded from
    QString descriptionVersion; // version stated by that file
};

// A fault/EMCY code a device can report, with its text from the device's documentation.
struct ErrorCodeDef
{
    quint32 code = 0;
    QString name;
    QString text;
    LocalTexts localTexts = {}; // text in further languages
};

// The objects of one device type, sorted by address. Value type; cheap to copy (implicitly
// shared containers).
class ObjectDictionary
{
public:
    DeviceIdentity identity;

    // How the objects' addresses are written: CANopen's hex INDEX:SUB unless the description
    // says otherwise (an inverter's parameter list is decimal NUMBER:DATASET). Never null.
    const AddressFormat &addressFormat() const
    {
        return m_addressFormat ? *m_addressFormat : AddressFormat::canopen();
    }
    void setAddressFormat(const AddressFormat &format) { m_addressFormat = &format; }

    void insert(const ObjectDef &def);
    const ObjectDef *find(ObjectAddress address) const;
    bool contains(ObjectAddress address) const { return m_objects.contains(address); }
    QList<ObjectDef> objects() const { return m_objects.values(); }
    QList<ObjectDef> subObjects(quint16 index) const;
    int size() const { return int(m_objects.size()); }
    bool isEmpty() const { return m_objects.isEmpty(); }

    void insertErrorCode(const ErrorCodeDef &def) { m_errors.insert(def.code, def); }
    std::optional<ErrorCodeDef> errorCode(quint32 code) const;
    // The device's own text for a code (in the language the program speaks where the description
    // has it), else the CiA 301 error class ("voltage", ...).
    QString errorText(quint32 code) const;

private:
    QMap<ObjectAddress, ObjectDef> m_objects;
    QMap<quint32, ErrorCodeDef> m_errors;
    const AddressFormat *m_addressFormat = nullptr; // null: canopen
};

// CiA 301 table 21: the error class of an emergency error code, e.g. 0x3221 -> "voltage".
QString cia301ErrorClassText(quint16 code);

} // namespace db
