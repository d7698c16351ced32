#pragma once
// One recorded signal: what it is and how its raw values are shown.
#include "core/addressformat.h"
#include "core/objectaddress.h"
#include "core/objectdef.h"
#include <QList>
#include <QMetaType>
#include <QString>

namespace db {

class ObjectDictionary;

namespace scope {

// Static description of a channel. Raw values are recorded as they come from the device;
// scale/offset only change how they are displayed and may be changed after recording
// (display = raw * scale + offset).
struct ChannelInfo
{
    QString id; // "6064:0", "372:2": the address as addressFormat writes it; unique per device
    ObjectAddress address;
    // How the device writes its addresses (CANopen's hex INDEX:SUB, or decimal NUMBER:DATASET
    // of inverter parameters). Never null.
    const AddressFormat *addressFormat = &AddressFormat::canopen();
    QString name; // "Position actual value"; may be empty for objects without description
    LocalTexts localNames = {}; // name in further languages (people read them, files keep name)
    QString unit; // unit of the displayed value ("inc", "mA"); may be empty
    QString device; // connection URI of the device the channel comes from
    // Short name of that device for people ("ACTIVE Cube ACU 127.0.0.1"); may be empty.
    QString deviceName;
    // Decimal places the displayed value has (an integer object's scale, a fixed-point
    // parameter's decimals); -1 when not fixed (floating-point values).
    int decimals = -1;
    double scale = 1.0;
    double offset = 0.0;
    int sourceRateMs = 0; // requested sample period; 0 = as fast as the link allows / event driven

    double display(double raw) const { return raw * scale + offset; }
    // The raw value that displays as `value` (inverse of display(); scale must not be 0).
    double raw(double value) const { return (value - offset) / scale; }
    // "6064:0 Position actual value" (the CSV column header and the CLI's name).
    QString label() const;
    // name and label in the language the program speaks, for the scope's legend and lists.
    QString displayName() const { return localText(name, localNames); }
    QString displayLabel() const;
    // "ACTIVE Cube ACU 127.0.0.1: 210 Actual frequency": displayLabel() with the device in
    // front (its name, else its URI), to tell the same object of two devices apart.
    QString deviceLabel() const;
    // The decimals to show a displayed value with: `decimals`, or for values without fixed
    // decimals enough for about five significant digits at `magnitude` (the largest absolute
    // value shown), at most 9.
    int displayDecimals(double magnitude) const;

    // A channel for `address` with name, unit and scaling (factor/offset) taken from the
    // dictionary when it knows the object; otherwise named by the address only. The id is
    // written in `format`, the dictionary's when null (pass the connection's).
    static ChannelInfo forObject(ObjectAddress address, const ObjectDictionary &dictionary,
                                 const QString &device, int rateMs = 0,
                                 const AddressFormat *format = nullptr);

    friend bool operator==(const ChannelInfo &, const ChannelInfo &) = default;
};

} // namespace scope
} // namespace db

Q_DECLARE_METATYPE(db::scope::ChannelInfo)
