#pragma once

// RefGo ASCII protocol vocabulary (movingcap.md section 3): the command table, request
// formatting (client) and parsing (device side), and result-line parsing. Pure functions.

#include "core/objectaddress.h"
#include "core/result.h"

#include <QList>
#include <QString>
#include <QVariant>

#include <optional>

namespace db::refgo {

// Every command of movingcap.md 3.3.
enum class Command {
    G,
    GW,
    PO,
    WA,
    SM,
    PWC,
    CM,
    REF,
    PQ,
    OW,
    OR,
    TPSR,
    TS,
    TP,
    SP,
    AC,
    DE,
    ACV,
    JP,
    JN,
    RR,
    RW,
    WT,
    SO,
    CO,
    TI,
};

enum class Parameter {
    None, // "SM"
    Optional, // "G" or "G10000", "JP" or "JP500"
    Required, // "SP500"
    Object, // OR/OW: "index,sub[,value|,h]"
};

enum class ResultKind {
    None, // echo + prompt only
    Integer, // one line, signed decimal (TP, TS, TI)
    Hex32, // one line, 8 hex digits (TPSR)
    ObjectRead, // "OR<index>,<sub>,<value>"
    ObjectWrite, // "<request>,OK"
};

struct CommandInfo
{
    Command command;
    const char *mnemonic; // "GW"
    Parameter parameter;
    ResultKind result;
    const char *title; // "Go Way" (English name from the manual)
};

const QList<CommandInfo> &commands();
const CommandInfo &info(Command command);

// ---- client side -------------------------------------------------------------------------

// "G10000", "SM", "JP500"
QString format(Command command, std::optional<qint64> argument = std::nullopt);
// Canonical "OR%04X,%X" or "OR%04X,%X,h" (spec 3.2 [R]).
QString formatRead(ObjectAddress address, bool hexOutput = false);
// "OW%04X,%X,%d"; value is a signed or unsigned integer QVariant (or bool).
QString formatWrite(ObjectAddress address, const QVariant &value);

// ---- device side -------------------------------------------------------------------------

struct Request
{
    Command command = Command::TP;
    QString text; // the request line as received, without CR
    std::optional<qint64> argument; // numeric parameter of the simple commands
    ObjectAddress address; // OR/OW
    QVariant value; // OW: qlonglong or qulonglong
    bool hexOutput = false; // OR: ",h" or "<sub>h"
};

// Parses one request line, tolerant as spec 3.2 and errata 15/16 ask: "OR 60FD,0",
// "OW 3510h,1,131072", "OR6041,0h", "OR3410H,1H", values in decimal or 0x hex.
// Lower-case mnemonics are accepted. InvalidArgument names what is wrong.
Result<Request> parseRequest(const QString &line);

// ---- results ------------------------------------------------------------------------------

// A numeric field of a reply: "-3658", "427h", "0x80", "3221h". Hex values are unsigned.
Result<qint64> parseNumber(const QString &text);

struct ObjectValue
{
    ObjectAddress address;
    qint64 value = 0; // as the drive printed it; hex output is read as an unsigned bit pattern
    bool hex = false;
};
// "OR6067,0,100", "OR 60FD,0,131072", "OR6041,0,427h", "OR3410H,1H,4242".
Result<ObjectValue> parseObjectRead(const QString &line);

// TPSR bits (movingcap.md 3.5).
struct ProcessStatus
{
    quint32 raw = 0;
    bool error() const { return raw & 0x001; }
    bool reference() const { return raw & 0x002; }
    bool inMotion() const { return raw & 0x004; }
    bool inPosition() const { return raw & 0x008; }
    bool inverterVoltage() const { return raw & 0x100; }
};
Result<ProcessStatus> parseTpsr(const QString &line);
QString formatTpsr(quint32 bits); // "0000000a": 8 lower-case hex digits

// TS values (movingcap.md 3.5).
enum class SimpleStatus { PowerOff = 0, PowerOn = 1, Moving = 2, Error = 9 };
Result<SimpleStatus> parseTs(const QString &line);
QString simpleStatusName(SimpleStatus status);

} // namespace db::refgo
