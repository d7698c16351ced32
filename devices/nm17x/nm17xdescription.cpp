#include "nm17xdescription.h"

#include "nm17xcodes.h"

#include <QCoreApplication>
#include <QSet>

namespace db::nm17x {

namespace {

enum class Valid { All, Motor, Nm174 };
namespace T {
constexpr DataType U8 = DataType::Unsigned8;
constexpr DataType U16 = DataType::Unsigned16;
constexpr DataType U32 = DataType::Unsigned32;
constexpr DataType I32 = DataType::Integer32;
constexpr DataType Str = DataType::VisibleString;
} // namespace T
namespace A {
constexpr Access Ro = Access::ReadOnly;
constexpr Access Rw = Access::ReadWrite;
constexpr Access Wo = Access::WriteOnly;
} // namespace A
using Store = Storage;

struct Entry
{
    quint16 index;
    quint8 sub;
    const char *name;
    const char *nameDe; // UTF-8: the term of the German manual
    DataType type;
    Access access;
    bool pdo;
    const char *defaultValue; // nullptr: none stated
    const char *minimum;
    const char *maximum;
    const char *unit;
    Storage storage;
    Valid valid;
};

// clang-format off
const Entry kEntries[] = {
    { 0x1000, 0, "Device type", "Gerätetyp", T::U32, A::Ro, false, "0x00020196", "0x00020196", "0x00020196", "", Store::None, Valid::All },
    { 0x1001, 0, "Error register", "Fehlerregister", T::U8, A::Ro, false, "0x00", "0", "255", "", Store::None, Valid::All },
    { 0x1002, 0, "Manufacturer status register", "Herstellerstatusregister", T::U32, A::Ro, false, {}, "0", {}, "", Store::None, Valid::All },
    { 0x1003, 0, "Number of errors", "Anzahl der Emergency-Meldungen", T::U8, A::Rw, false, "0", "0", "8", "", Store::None, Valid::All },
    { 0x1003, 1, "Standard error field 1", "Aufgetretene Emergency-Meldung 1", T::U32, A::Ro, false, {}, "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x1003, 2, "Standard error field 2", "Aufgetretene Emergency-Meldung 2", T::U32, A::Ro, false, {}, "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x1003, 3, "Standard error field 3", "Aufgetretene Emergency-Meldung 3", T::U32, A::Ro, false, {}, "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x1003, 4, "Standard error field 4", "Aufgetretene Emergency-Meldung 4", T::U32, A::Ro, false, {}, "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x1003, 5, "Standard error field 5", "Aufgetretene Emergency-Meldung 5", T::U32, A::Ro, false, {}, "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x1003, 6, "Standard error field 6", "Aufgetretene Emergency-Meldung 6", T::U32, A::Ro, false, {}, "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x1003, 7, "Standard error field 7", "Aufgetretene Emergency-Meldung 7", T::U32, A::Ro, false, {}, "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x1003, 8, "Standard error field 8", "Aufgetretene Emergency-Meldung 8", T::U32, A::Ro, false, {}, "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x1005, 0, "COB-ID SYNC", "COB-ID SYNC", T::U32, A::Rw, false, "0x00000080", {}, {}, "", Store::Flash, Valid::All },
    { 0x1008, 0, "Manufacturer device name", "Gerätename des Herstellers", T::Str, A::Ro, false, "NM170 Standard", {}, {}, "", Store::None, Valid::All },
    { 0x1009, 0, "Manufacturer hardware version", "Hardwareversion des Herstellers", T::Str, A::Ro, false, {}, {}, {}, "", Store::None, Valid::All },
    { 0x100A, 0, "Manufacturer software version", "Softwareversion des Herstellers", T::Str, A::Ro, false, {}, {}, {}, "", Store::None, Valid::All },
    { 0x1010, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::All },
    { 0x1010, 1, "Save all parameters", "Alle Parameter speichern", T::U32, A::Rw, false, "0x00000001", {}, {}, "", Store::Flash, Valid::All },
    { 0x1010, 2, "Save communication parameters", "Kommunikationsparameter speichern", T::U32, A::Rw, false, "0x00000001", {}, {}, "", Store::Flash, Valid::All },
    { 0x1011, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::All },
    { 0x1011, 1, "Restore all default parameters", "Alle Parameter auf Werkseinstellung", T::U32, A::Rw, false, "0x00000001", {}, {}, "", Store::Flash, Valid::All },
    { 0x1011, 2, "Restore communication default parameters", "Kommunikationsparameter auf Werkseinstellung", T::U32, A::Rw, false, "0x00000001", {}, {}, "", Store::Flash, Valid::All },
    { 0x1014, 0, "COB-ID EMCY", "COB-ID Emergency", T::U32, A::Rw, false, "0x80", "0x00000081", "0x000000FF", "", Store::Flash, Valid::All },
    { 0x1016, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "1", {}, {}, "", Store::None, Valid::All },
    { 0x1016, 1, "Consumer heartbeat time 1", "Consumer-Heartbeat-Zeit 1", T::U32, A::Rw, false, "0", "0", "0xFFFFFFFF", "ms", Store::Flash, Valid::All },
    { 0x1017, 0, "Producer heartbeat time", "Producer-Heartbeat-Zeit", T::U16, A::Rw, false, "0", "0", "65535", "ms", Store::Flash, Valid::All },
    { 0x1018, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "4", {}, {}, "", Store::None, Valid::All },
    { 0x1018, 1, "Vendor-ID", "Hersteller-ID", T::U32, A::Ro, false, "0x000000EC", "0x000000EC", "0x000000EC", "", Store::None, Valid::All },
    { 0x1018, 2, "Product code", "Produktcode", T::U32, A::Ro, false, "0x00000070", "0x00000070", "0x00000072", "", Store::None, Valid::All },
    { 0x1018, 3, "Revision number", "Revisionsnummer", T::U32, A::Ro, false, "0x00010001", {}, {}, "", Store::None, Valid::All },
    { 0x1018, 4, "Serial number", "Seriennummer", T::U32, A::Ro, false, {}, {}, {}, "", Store::None, Valid::All },
    { 0x1029, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::All },
    { 0x1029, 1, "Communication error", "Verhalten bei Kommunikationsfehler", T::U8, A::Rw, false, "0", "0", "2", "", Store::Flash, Valid::All },
    { 0x1029, 2, "Manufacturer specific error", "Verhalten bei herstellerspezifischem Fehler", T::U8, A::Rw, false, "1", "0", "2", "", Store::Flash, Valid::All },
    { 0x1400, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::All },
    { 0x1400, 1, "COB-ID used by RPDO", "COB-ID des RPDO", T::U32, A::Rw, false, "0x40000201", {}, {}, "", Store::Flash, Valid::All },
    { 0x1400, 2, "Transmission type", "Übertragungsart", T::U8, A::Rw, false, "0xFF", "0xFF", "0xFF", "", Store::Flash, Valid::All },
    { 0x1401, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::All },
    { 0x1401, 1, "COB-ID used by RPDO", "COB-ID des RPDO", T::U32, A::Rw, false, "0x4000037F", {}, {}, "", Store::Flash, Valid::All },
    { 0x1401, 2, "Transmission type", "Übertragungsart", T::U8, A::Rw, false, "0xFF", "0xFF", "0xFF", "", Store::Flash, Valid::All },
    { 0x1600, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "4", {}, {}, "", Store::None, Valid::All },
    { 0x1600, 1, "Mapping entry 1", "Mapping-Eintrag 1 (Broadcast Control)", T::U32, A::Ro, false, "0x25000108", "0x25000108", "0x25000108", "", Store::None, Valid::All },
    { 0x1600, 2, "Mapping entry 2", "Mapping-Eintrag 2 (Broadcast Objekt)", T::U32, A::Ro, false, "0x25000210", "0x25000210", "0x25000210", "", Store::None, Valid::All },
    { 0x1600, 3, "Mapping entry 3", "Mapping-Eintrag 3 (Broadcast Subindex)", T::U32, A::Ro, false, "0x25000308", "0x25000308", "0x25000308", "", Store::None, Valid::All },
    { 0x1600, 4, "Mapping entry 4", "Mapping-Eintrag 4 (Broadcast Daten)", T::U32, A::Ro, false, "0x25000420", "0x25000420", "0x25000420", "", Store::None, Valid::All },
    { 0x1601, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "3", {}, {}, "", Store::None, Valid::All },
    { 0x1601, 1, "Mapping entry 1", "Mapping-Eintrag 1 (Sollwert)", T::U32, A::Ro, false, "0x25010120", "0x25010120", "0x25010120", "", Store::None, Valid::All },
    { 0x1601, 2, "Mapping entry 2", "Mapping-Eintrag 2 (Istwertkorrektur)", T::U32, A::Ro, false, "0x25010210", "0x25010210", "0x25010210", "", Store::None, Valid::All },
    { 0x1601, 3, "Mapping entry 3", "Mapping-Eintrag 3 (Control-Register)", T::U32, A::Ro, false, "0x25010310", "0x25010310", "0x25010310", "", Store::None, Valid::All },
    { 0x1800, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "5", {}, {}, "", Store::None, Valid::All },
    { 0x1800, 1, "COB-ID used by TPDO", "COB-ID des TPDO", T::U32, A::Rw, false, "0xC00001FF", {}, {}, "", Store::Flash, Valid::All },
    { 0x1800, 2, "Transmission type", "Übertragungsart", T::U8, A::Rw, false, "0xFF", "0x01", "0xFF", "", Store::Flash, Valid::All },
    { 0x1800, 3, "Inhibit time", "Sperrzeit", T::U16, A::Rw, false, "80", "0", "65535", "ms", Store::Flash, Valid::All },
    { 0x1800, 5, "Event timer", "Ereignis-Timer", T::U16, A::Rw, false, "1000", "0", "65535", "ms", Store::Flash, Valid::All },
    { 0x1801, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "5", {}, {}, "", Store::None, Valid::All },
    { 0x1801, 1, "COB-ID used by TPDO", "COB-ID des TPDO", T::U32, A::Rw, false, "0x400002FF", {}, {}, "", Store::Flash, Valid::All },
    { 0x1801, 2, "Transmission type", "Übertragungsart", T::U8, A::Rw, false, "0xFF", "0x01", "0xFF", "", Store::Flash, Valid::All },
    { 0x1801, 3, "Inhibit time", "Sperrzeit", T::U16, A::Rw, false, "80", "0", "65535", "ms", Store::Flash, Valid::All },
    { 0x1801, 5, "Event timer", "Ereignis-Timer", T::U16, A::Rw, false, "1", "0", "65535", "ms", Store::Flash, Valid::All },
    { 0x1A00, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "3", {}, {}, "", Store::None, Valid::All },
    { 0x1A00, 1, "Mapping entry 1", "Mapping-Eintrag 1 (Position)", T::U32, A::Ro, false, "0x60040020", "0x60040020", "0x60040020", "", Store::None, Valid::All },
    { 0x1A00, 2, "Mapping entry 2", "Mapping-Eintrag 2 (SPA-Status)", T::U32, A::Ro, false, "0x204E0110", "0x204E0110", "0x204E0110", "", Store::None, Valid::All },
    { 0x1A00, 3, "Mapping entry 3", "Mapping-Eintrag 3 (SPA-Fehler)", T::U32, A::Ro, false, "0x204E0210", "0x204E0210", "0x204E0210", "", Store::None, Valid::All },
    { 0x1A01, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "3", {}, {}, "", Store::None, Valid::All },
    { 0x1A01, 1, "Mapping entry 1", "Mapping-Eintrag 1 (Position)", T::U32, A::Ro, false, "0x60040020", "0x60040020", "0x60040020", "", Store::None, Valid::All },
    { 0x1A01, 2, "Mapping entry 2", "Mapping-Eintrag 2 (Istwertkorrektur)", T::U32, A::Ro, false, "0x25010410", "0x25010410", "0x25010410", "", Store::None, Valid::All },
    { 0x1A01, 3, "Mapping entry 3", "Mapping-Eintrag 3 (SPA-Status)", T::U32, A::Ro, false, "0x204E0110", "0x204E0110", "0x204E0110", "", Store::None, Valid::All },
    { 0x1F80, 0, "NMT startup", "NMT-Startverhalten", T::U32, A::Rw, false, "0", "0", "8", "", Store::Flash, Valid::All },
    { 0x2000, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "8", {}, {}, "", Store::None, Valid::All },
    { 0x2000, 1, "Positioning direction", "Positionierrichtung", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::All },
    { 0x2000, 2, "Counting direction", "Zählrichtung", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::All },
    { 0x2000, 3, "Arrows", "Pfeile", T::U32, A::Rw, false, "0", "0", "5", "", Store::Eeprom, Valid::All },
    { 0x2000, 4, "Round actual value", "Istwert runden", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::All },
    { 0x2000, 5, "Rotate display", "Display drehen", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::All },
    { 0x2000, 6, "Actual value correction on/off", "Istwertkorrektur ein/aus", T::U32, A::Rw, false, "1", "0", "1", "", Store::Eeprom, Valid::All },
    { 0x2000, 7, "Hide setpoint", "Sollwert ausblenden", T::U32, A::Rw, false, "0", "0", "2", "", Store::Eeprom, Valid::All },
    { 0x2000, 8, "External inputs", "Externe Eingänge", T::U32, A::Rw, false, "0", "0", "3", "", Store::Eeprom, Valid::All },
    { 0x2001, 0, "Length unit", "Längeneinheit", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::All },
    { 0x2002, 0, "Loop length for backlash compensation", "Schleife für Spindelspielausgleich", T::U32, A::Rw, false, "100", "0", "9999", "1/100 mm", Store::Eeprom, Valid::All },
    { 0x2003, 0, "Tolerance window", "Toleranzfenster", T::U32, A::Rw, false, "5", "0", "9999", "1/100 mm", Store::Eeprom, Valid::All },
    { 0x2004, 0, "Scaling (spindle pitch)", "Skalierung (Spindelsteigung)", T::U32, A::Rw, false, "1736111", "0", "99999999", "1e-7", Store::Eeprom, Valid::All },
    { 0x2005, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "3", {}, {}, "", Store::None, Valid::All },
    { 0x2005, 1, "Filter width", "Filterbreite", T::U32, A::Rw, false, "100", "0", "2303", "steps", Store::Eeprom, Valid::All },
    { 0x2005, 2, "Filter count", "Filteranzahl", T::U32, A::Rw, false, "5", "0", "99", "", Store::Eeprom, Valid::All },
    { 0x2005, 3, "LCD digit right off", "Rechte LCD-Stelle ausblenden", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::All },
    { 0x2006, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::All },
    { 0x2006, 1, "MSP firmware version", "Firmwareversion MSP-Controller", T::U32, A::Ro, false, {}, "105", {}, "", Store::None, Valid::All },
    { 0x2006, 2, "MSP firmware device type", "Gerätetyp MSP-Controller", T::U32, A::Ro, false, {}, {}, {}, "", Store::None, Valid::All },
    { 0x2007, 0, "Display message", "Displaymeldung", T::Str, A::Rw, false, "1234567890AB", {}, {}, "", Store::Ram, Valid::All },
    { 0x2008, 0, "Show node-ID", "Adresse anzeigen", T::U32, A::Wo, false, {}, "0", "1", "", Store::None, Valid::All },
    { 0x2010, 0, "Actual value correction (offset)", "Istwertkorrektur (Offset)", T::I32, A::Rw, false, "0", "-99999", "999999", "1/100 mm", Store::Eeprom, Valid::All },
    { 0x2015, 0, "Device reset functions", "SPA rücksetzen", T::U32, A::Wo, false, {}, "1", "6", "", Store::Eeprom, Valid::All },
    { 0x2020, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "8", {}, {}, "", Store::None, Valid::All },
    { 0x2020, 1, "Setpoint S (standard)", "Sollwert S (Standard)", T::I32, A::Rw, false, "1000", "-99999", "999999", "1/100 mm", Store::Eeprom, Valid::All },
    { 0x2020, 2, "Setpoint SF (standard, with motor enable)", "Sollwert SF (Standard, mit Motorfreigabe)", T::I32, A::Rw, false, "1000", "-99999", "999999", "1/100 mm", Store::Eeprom, Valid::Motor },
    { 0x2020, 3, "Setpoint SD (dimension)", "Sollwert Direkt SD", T::I32, A::Rw, false, "0", "-99999", "999999", "1/100 mm", Store::Ram, Valid::Motor },
    { 0x2020, 4, "Setpoint SDF (dimension, with motor enable)", "Sollwert Direkt SDF (mit Motorfreigabe)", T::I32, A::Rw, false, "0", "-99999", "999999", "1/100 mm", Store::Ram, Valid::Motor },
    { 0x2020, 5, "Setpoint SEF (direct, no loop, with motor enable)", "Sollwert Direkt SEF (mit Motorfreigabe, ohne Spielausgleich)", T::I32, A::Rw, false, "0", "-99999", "999999", "1/100 mm", Store::Ram, Valid::Motor },
    { 0x2020, 6, "Setpoint SL (plunge cut)", "Sollwert Einsägen SL", T::I32, A::Rw, false, "0", "-99999", "999999", "1/100 mm", Store::Ram, Valid::Motor },
    { 0x2020, 7, "Setpoint SLF (plunge cut, with motor enable)", "Sollwert Einsägen SLF (mit Motorfreigabe)", T::I32, A::Rw, false, "0", "-99999", "999999", "1/100 mm", Store::Ram, Valid::Motor },
    { 0x2020, 8, "Speed for plunge cut function", "Geschwindigkeit für Funktion Einsägen", T::U32, A::Rw, false, "0", "0", "2", "", Store::Eeprom, Valid::Motor },
    { 0x2040, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "4", {}, {}, "", Store::None, Valid::Motor },
    { 0x2040, 1, "Key assignment", "Tastenzuordnung", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::Motor },
    { 0x2040, 2, "Motor direction", "Drehrichtung Motor", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::Motor },
    { 0x2040, 3, "Jog activation", "Aktivierung Jog", T::U32, A::Rw, false, "0", "0", "3", "", Store::Eeprom, Valid::Motor },
    { 0x2040, 4, "Group setting", "Gruppeneinstellung", T::U32, A::Rw, false, "0", "0", "7", "", Store::Eeprom, Valid::Motor },
    { 0x2041, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "4", {}, {}, "", Store::None, Valid::Motor },
    { 0x2041, 1, "Collision on/off", "Kollision ein/aus", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::Motor },
    { 0x2041, 2, "Dynamic pre-shutdown", "Dynamische Vorabschaltung", T::U32, A::Rw, false, "0", "0", "1", "", Store::Eeprom, Valid::Motor },
    { 0x2041, 3, "Input modes", "Eingangsmodi", T::U32, A::Rw, false, "0", "0", "3", "", Store::Eeprom, Valid::Motor },
    { 0x2041, 4, "Key modes", "Tastenmodi", T::U32, A::Rw, false, "0", "0", "3", "", Store::Eeprom, Valid::Motor },
    { 0x2042, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "3", {}, {}, "", Store::None, Valid::Motor },
    { 0x2042, 1, "Slow-speed switch point", "Schaltpunkt Schleichgang", T::U32, A::Rw, false, "0", "0", "9999", "1/100 mm", Store::Eeprom, Valid::Motor },
    { 0x2042, 2, "Creep-speed switch point", "Schaltpunkt Kriechgang", T::U32, A::Rw, false, "150", "0", "9999", "1/100 mm", Store::Eeprom, Valid::Motor },
    { 0x2042, 3, "Switch-off point", "Abschaltpunkt", T::I32, A::Rw, false, "0", "-9999", "9999", "1/100 mm", Store::Eeprom, Valid::Motor },
    { 0x2043, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::Motor },
    { 0x2043, 1, "End limit MIN", "Endlage MIN", T::I32, A::Rw, false, "-99999", "-99999", "999998", "1/100 mm", Store::Eeprom, Valid::Motor },
    { 0x2043, 2, "End limit MAX", "Endlage MAX", T::I32, A::Rw, false, "999999", "-99998", "999999", "1/100 mm", Store::Eeprom, Valid::Motor },
    { 0x2044, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::Motor },
    { 0x2044, 1, "Collision MIN", "Kollision MIN", T::I32, A::Rw, false, "-99999", "-99999", "999998", "1/100 mm", Store::Eeprom, Valid::Motor },
    { 0x2044, 2, "Collision MAX", "Kollision MAX", T::I32, A::Rw, false, "999999", "-99998", "999999", "1/100 mm", Store::Eeprom, Valid::Motor },
    { 0x2045, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "3", {}, {}, "", Store::None, Valid::Motor },
    { 0x2045, 1, "Setpoint D1", "Sollwert D1", T::I32, A::Rw, false, "-99999", "-99999", "999999", "1/100 mm", Store::Ram, Valid::Motor },
    { 0x2045, 2, "Setpoint D2", "Sollwert D2", T::I32, A::Rw, false, "999999", "-99999", "999999", "1/100 mm", Store::Ram, Valid::Motor },
    { 0x2045, 3, "Setpoint D3", "Sollwert D3", T::I32, A::Rw, false, "0", "-99999", "999999", "1/100 mm", Store::Ram, Valid::Motor },
    { 0x2046, 0, "Jog step width", "Schrittweite für Jog-Funktion", T::U32, A::Rw, false, "1", "0", "9999", "", Store::Eeprom, Valid::Motor },
    { 0x2047, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "3", {}, {}, "", Store::None, Valid::Motor },
    { 0x2047, 1, "Loop dwell time", "Schleifenzeit", T::U32, A::Rw, false, "10", "1", "999", "0.1 s", Store::Eeprom, Valid::Motor },
    { 0x2047, 2, "Following error time", "Schleppfehlerzeit", T::U32, A::Rw, false, "30", "1", "999", "0.1 s", Store::Eeprom, Valid::Motor },
    { 0x2047, 3, "Clamping", "Klemmung", T::U32, A::Rw, false, "0", "0", "999", "0.1 s", Store::Eeprom, Valid::Motor },
    { 0x2048, 0, "Clamping open/close", "Klemmung öffnen/schließen", T::U8, A::Rw, false, {}, "0", "2", "", Store::None, Valid::Motor },
    { 0x204D, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::Motor },
    { 0x204D, 1, "Positioning start/stop", "Positionierung Start/Stopp", T::U8, A::Rw, false, {}, "0", "8", "", Store::None, Valid::Motor },
    { 0x204D, 2, "Oscillation start/stop", "Oszillieren Start/Stopp", T::U8, A::Rw, false, {}, "0", "1", "", Store::None, Valid::Motor },
    { 0x204D, 3, "Start jog", "Tippen starten", T::U8, A::Rw, false, "0", "11", "23", "", Store::None, Valid::Motor },
    { 0x204E, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "2", {}, {}, "", Store::None, Valid::Motor },
    { 0x204E, 1, "Device status", "SPA-Status", T::U16, A::Ro, true, {}, "0", "65535", "", Store::None, Valid::Motor },
    { 0x204E, 2, "Device errors", "SPA-Fehler", T::U16, A::Ro, true, {}, "0", "65535", "", Store::None, Valid::Motor },
    { 0x2060, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "3", {}, {}, "", Store::None, Valid::Nm174 },
    { 0x2060, 1, "SSI data width", "Auflösung SSI-Wert (Datenbreite)", T::U32, A::Rw, false, "25", "12", "32", "bit", Store::Eeprom, Valid::Nm174 },
    { 0x2060, 2, "SSI code", "SSI-Code", T::U32, A::Rw, false, "1", "0", "1", "", Store::Eeprom, Valid::Nm174 },
    { 0x2060, 3, "Sensor type", "Sensortyp", T::U32, A::Rw, false, "0", "0", "9", "", Store::Eeprom, Valid::Nm174 },
    { 0x2100, 0, "Bit rate", "Baudrate", T::U8, A::Rw, false, "5", "0", "8", "", Store::Flash, Valid::All },
    { 0x2101, 0, "Node-ID", "Node-ID", T::U8, A::Rw, false, "127", "1", "127", "", Store::Flash, Valid::All },
    { 0x2500, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "4", {}, {}, "", Store::None, Valid::All },
    { 0x2500, 1, "Broadcast control register", "Broadcast-Control-Register", T::U8, A::Rw, true, "0", "0", "255", "", Store::None, Valid::All },
    { 0x2500, 2, "Broadcast object index", "Broadcast-Objektnummer", T::U16, A::Rw, true, "0", "0", "65535", "", Store::None, Valid::All },
    { 0x2500, 3, "Broadcast sub-index", "Broadcast-Subindex", T::U8, A::Rw, true, "0", "0", "255", "", Store::None, Valid::All },
    { 0x2500, 4, "Broadcast data", "Broadcast-Daten", T::U32, A::Rw, true, "0", "0", "0xFFFFFFFF", "", Store::None, Valid::All },
    { 0x2501, 0, "Highest sub-index supported", "Größter Subindex", T::U8, A::Ro, false, "4", {}, {}, "", Store::None, Valid::All },
    { 0x2501, 1, "PDO setpoint", "PDO-Sollwert", T::U32, A::Rw, true, "0", "0", "0xFFFFFFFF", "1/100 mm", Store::None, Valid::All },
    { 0x2501, 2, "PDO actual value correction (RxPDO2)", "PDO-Istwertkorrektur (RxPDO2)", T::U16, A::Rw, true, "0", "0", "65535", "1/100 mm", Store::None, Valid::All },
    { 0x2501, 3, "PDO control register", "PDO-Control-Register", T::U16, A::Rw, true, "0", "0", "65535", "", Store::None, Valid::All },
    { 0x2501, 4, "PDO actual value correction (TxPDO2 copy)", "PDO-Istwertkorrektur (Kopie für TxPDO2)", T::U16, A::Rw, true, "0", "0", "65535", "1/100 mm", Store::None, Valid::All },
    { 0x6003, 0, "Preset value", "Preset", T::I32, A::Rw, false, {}, "-99999", "999999", "1/100 mm", Store::Eeprom, Valid::All },
    { 0x6004, 0, "Position value", "Position (Istwert)", T::I32, A::Ro, true, {}, "-99999", "999999", "1/100 mm", Store::None, Valid::All },
};
// clang-format on

QVariant number(const char *text, DataType type)
{
    if (!text)
        return {};
    const QString s = QString::fromLatin1(text);
    if (type == DataType::VisibleString)
        return s;
    bool ok = false;
    const qlonglong v = s.startsWith(QLatin1String("0x")) ? qlonglong(s.mid(2).toULongLong(&ok, 16))
                                                          : s.toLongLong(&ok);
    return ok ? QVariant(v) : QVariant();
}

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(Nm17x)
};

// `local` (a translated text) as the name in the language the program speaks, unless it is the
// English one.
LocalTexts localName(const QString &english, const QString &local)
{
    const QString language = textLanguage();
    if (language == QLatin1String("en") || local.endsWith(english))
        return {};
    return { { language, local } };
}

using Names = std::initializer_list<std::pair<qlonglong, const char *>>;

// An enumeration in English (what files and the command line's fixed output write) with its
// text in the language the program speaks while the dictionary is built (one per connection).
void setNames(ObjectDef &def, Names names)
{
    const QString language = textLanguage();
    for (const auto &[value, english] : names) {
        def.enumeration.insert(value, QString::fromLatin1(english));
        const QString local = Tr::tr(english);
        if (language != QLatin1String("en") && local != QLatin1String(english))
            def.localEnumeration[value].insert(language, local);
    }
}

// An enumeration value with a number ("group %1").
void setName(ObjectDef &def, qlonglong value, const char *english, int number)
{
    def.enumeration.insert(value, QString::fromLatin1(english).arg(number));
    const QString language = textLanguage();
    if (language != QLatin1String("en"))
        def.localEnumeration[value].insert(language, Tr::tr(english).arg(number));
}

constexpr std::pair<qlonglong, const char *> kUp = { 0, QT_TRANSLATE_NOOP("Nm17x", "Up") };
constexpr std::pair<qlonglong, const char *> kDown = { 1, QT_TRANSLATE_NOOP("Nm17x", "Down") };

// Enumerations, bit fields and texts of the objects an operator sets up.
void describe(ObjectDef &def)
{
    const quint32 key = (quint32(def.address.index) << 8) | def.address.sub;
    switch (key) {
    case 0x200001:
        setNames(def, { kUp, kDown });
        def.description = Tr::tr("Side from which the target is approached (loop for backlash "
                                 "compensation)");
        break;
    case 0x200002:
        setNames(def, { kUp, kDown });
        def.description = Tr::tr("Up: turning the shaft right increases the actual value");
        break;
    case 0x200003:
        setNames(def,
                 { { 0, QT_TRANSLATE_NOOP("Nm17x", "Up") },
                   { 1, QT_TRANSLATE_NOOP("Nm17x", "Down") },
                   { 2, QT_TRANSLATE_NOOP("Nm17x", "Uni") },
                   { 3, QT_TRANSLATE_NOOP("Nm17x", "Off") },
                   { 4, QT_TRANSLATE_NOOP("Nm17x", "Uni-Loop") },
                   { 5, QT_TRANSLATE_NOOP("Nm17x", "Off-Loop") } });
        def.description = Tr::tr("Direction arrows; Uni and Off position without loop");
        break;
    case 0x200004:
    case 0x200005:
        setNames(
            def,
            { { 0, QT_TRANSLATE_NOOP("Nm17x", "Off") }, { 1, QT_TRANSLATE_NOOP("Nm17x", "On") } });
        break;
    case 0x200006:
        setNames(
            def,
            { { 0, QT_TRANSLATE_NOOP("Nm17x", "Off") }, { 1, QT_TRANSLATE_NOOP("Nm17x", "On") } });
        def.description = Tr::tr("On: the correction 2010h is added to actual value and setpoint");
        break;
    case 0x200007:
        setNames(def,
                 { { 0, QT_TRANSLATE_NOOP("Nm17x", "On") },
                   { 1, QT_TRANSLATE_NOOP("Nm17x", "Off") },
                   { 2, QT_TRANSLATE_NOOP("Nm17x", "Ever") } });
        break;
    case 0x200008:
        setNames(def,
                 { { 0, QT_TRANSLATE_NOOP("Nm17x", "Key") },
                   { 1, QT_TRANSLATE_NOOP("Nm17x", "Slow") },
                   { 2, QT_TRANSLATE_NOOP("Nm17x", "Middle") },
                   { 3, QT_TRANSLATE_NOOP("Nm17x", "Fast") } });
        break;
    case 0x200100:
        def.enumeration = { { 0, QStringLiteral("mm") }, { 1, QStringLiteral("inch") } };
        def.description = Tr::tr("Display only: values on the bus stay in 1/100 mm");
        break;
    case 0x202008:
        setNames(def,
                 { { 0, QT_TRANSLATE_NOOP("Nm17x", "slow") },
                   { 1, QT_TRANSLATE_NOOP("Nm17x", "medium") },
                   { 2, QT_TRANSLATE_NOOP("Nm17x", "fast") } });
        break;
    case 0x204001:
    case 0x204002:
        setNames(def, { kUp, kDown });
        break;
    case 0x204003:
        setNames(def,
                 { { 0, QT_TRANSLATE_NOOP("Nm17x", "Up") },
                   { 1, QT_TRANSLATE_NOOP("Nm17x", "Down") },
                   { 2, QT_TRANSLATE_NOOP("Nm17x", "Ever") },
                   { 3, QT_TRANSLATE_NOOP("Nm17x", "Off") } });
        break;
    case 0x204004:
        for (int g = 0; g < 8; ++g)
            setName(def, g, QT_TRANSLATE_NOOP("Nm17x", "group %1"), g + 1);
        break;
    case 0x204101:
        setNames(
            def,
            { { 0, QT_TRANSLATE_NOOP("Nm17x", "On") }, { 1, QT_TRANSLATE_NOOP("Nm17x", "Off") } });
        break;
    case 0x204102:
        setNames(
            def,
            { { 0, QT_TRANSLATE_NOOP("Nm17x", "Off") }, { 1, QT_TRANSLATE_NOOP("Nm17x", "On") } });
        break;
    case 0x204103:
        setNames(def,
                 { { 0, QT_TRANSLATE_NOOP("Nm17x", "Standard / Oscillating") },
                   { 1, QT_TRANSLATE_NOOP("Nm17x", "Takten") },
                   { 2, QT_TRANSLATE_NOOP("Nm17x", "ExternPosi") },
                   { 3, QT_TRANSLATE_NOOP("Nm17x", "Off") } });
        break;
    case 0x204104:
        setNames(def,
                 { { 0, QT_TRANSLATE_NOOP("Nm17x", "Standard") },
                   { 1, QT_TRANSLATE_NOOP("Nm17x", "Slow") },
                   { 2, QT_TRANSLATE_NOOP("Nm17x", "Middle") },
                   { 3, QT_TRANSLATE_NOOP("Nm17x", "Fast") } });
        break;
    case 0x204D01:
        setNames(def, { { 0, QT_TRANSLATE_NOOP("Nm17x", "stop") } });
        for (int g = 1; g <= 8; ++g)
            setName(def, g, QT_TRANSLATE_NOOP("Nm17x", "start group %1"), g);
        break;
    case 0x204D03:
        setNames(def,
                 { { 11, QT_TRANSLATE_NOOP("Nm17x", "right slow") },
                   { 12, QT_TRANSLATE_NOOP("Nm17x", "right medium") },
                   { 13, QT_TRANSLATE_NOOP("Nm17x", "right fast") },
                   { 21, QT_TRANSLATE_NOOP("Nm17x", "left slow") },
                   { 22, QT_TRANSLATE_NOOP("Nm17x", "left medium") },
                   { 23, QT_TRANSLATE_NOOP("Nm17x", "left fast") } });
        break;
    case 0x204E01:
        for (const BitText &b : statusBits())
            def.bitFields.append({ b.bit, 1, b.english, localName(b.english, b.name) });
        def.traceable = true;
        break;
    case 0x204E02:
        for (const DisplayError &e : displayErrors())
            def.bitFields.append(
                { e.bit, 1, QStringLiteral("%1 %2").arg(e.code, e.englishText),
                  localName(e.englishText, QStringLiteral("%1 %2").arg(e.code, e.text)) });
        def.traceable = true;
        break;
    case 0x210000:
        def.enumeration = {
            { 0, QStringLiteral("10 kbit/s") },  { 1, QStringLiteral("20 kbit/s") },
            { 2, QStringLiteral("50 kbit/s") },  { 3, QStringLiteral("100 kbit/s") },
            { 4, QStringLiteral("125 kbit/s") }, { 5, QStringLiteral("250 kbit/s") },
            { 6, QStringLiteral("500 kbit/s") }, { 7, QStringLiteral("800 kbit/s") },
            { 8, QStringLiteral("1000 kbit/s") }
        };
        def.description = Tr::tr("Takes effect at the next Reset Node");
        break;
    case 0x210100:
        def.description = Tr::tr("Takes effect at the next Reset Node");
        break;
    case 0x600400:
        def.traceable = true;
        break;
    default:
        break;
    }
}

} // namespace

quint32 productCode(Variant v)
{
    return 0x70 + quint32(v);
}

QString variantName(Variant v)
{
    return QStringLiteral("NM17%1").arg(2 * int(v));
}

QString deviceName(Variant v)
{
    return variantName(v) + QStringLiteral(" Standard");
}

quint32 mspDeviceType(Variant v)
{
    return 0x8081 + 0x200 * quint32(v);
}

bool hasMotor(Variant v)
{
    return v != Variant::Nm170;
}

std::optional<Variant> variantOf(quint32 vendorId, quint32 product)
{
    if (vendorId != kVendorId || product < 0x70 || product > 0x72)
        return std::nullopt;
    return Variant(product - 0x70);
}

std::optional<Variant> parseVariant(const QString &text)
{
    for (const Variant v : { Variant::Nm170, Variant::Nm172, Variant::Nm174 }) {
        if (text.compare(variantName(v), Qt::CaseInsensitive) == 0)
            return v;
    }
    return std::nullopt;
}

Storage storageOf(ObjectAddress address)
{
    for (const Entry &e : kEntries) {
        if (e.index == address.index && e.sub == address.sub)
            return e.storage;
    }
    return Storage::None;
}

ObjectDictionary dictionary(Variant v, canopen::NodeId node)
{
    ObjectDictionary d;
    d.identity.vendorName = QStringLiteral("Baumer Germany GmbH & Co. KG");
    d.identity.vendorId = kVendorId;
    d.identity.productName = variantName(v);
    d.identity.productCode = productCode(v);
    d.identity.descriptionFile = QStringLiteral("drivebench nm17x");
    for (const Entry &e : kEntries) {
        if ((e.valid == Valid::Motor && !hasMotor(v))
            || (e.valid == Valid::Nm174 && v != Variant::Nm174))
            continue;
        ObjectDef def;
        def.address = ObjectAddress(e.index, e.sub);
        def.name = QString::fromLatin1(e.name);
        def.localNames.insert(QStringLiteral("de"), QString::fromUtf8(e.nameDe));
        def.type = e.type;
        def.access = e.access;
        def.pdoMappable = e.pdo;
        def.unit = QString::fromLatin1(e.unit);
        def.defaultValue = number(e.defaultValue, e.type);
        def.minimum = number(e.minimum, e.type);
        def.maximum = number(e.maximum, e.type);
        def.storable = e.storage == Storage::Eeprom || e.storage == Storage::Flash;
        describe(def);
        d.insert(def);
    }
    // Values that depend on the variant or the node id.
    const auto set = [&d](ObjectAddress a, const QVariant &value) {
        if (const ObjectDef *old = d.find(a)) {
            ObjectDef def = *old;
            def.defaultValue = value;
            d.insert(def);
        }
    };
    set({ 0x1008, 0 }, deviceName(v));
    set({ 0x1018, 2 }, productCode(v));
    set({ 0x2006, 2 }, mspDeviceType(v));
    set({ 0x1014, 0 }, 0x80 + node);
    set({ 0x1401, 1 }, 0x40000300 + node);
    set({ 0x1800, 1 }, 0xC0000180 + node);
    set({ 0x1801, 1 }, 0x40000280 + node);
    if (!hasMotor(v)) {
        ObjectDef arrows = *d.find({ 0x2000, 3 });
        arrows.maximum = 3;
        arrows.enumeration.remove(4);
        arrows.enumeration.remove(5);
        d.insert(arrows);
    }
    if (v == Variant::Nm174)
        set({ 0x2005, 2 }, 2);
    QSet<quint16> seen;
    for (const EmcyCode &e : emcyCodes()) {
        if (seen.contains(e.code))
            continue;
        seen.insert(e.code);
        d.insertErrorCode(
            { e.code, QStringLiteral("%1h").arg(QString::number(e.code, 16).toUpper()), e.text });
    }
    return d;
}

} // namespace db::nm17x
