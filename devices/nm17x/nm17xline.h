#pragma once

// The master's services for a line of NM170/NM172/NM174 displays on one CAN network:
// positioning commands through RxPDO2 (300h + node) built only from the allowed control words,
// the broadcast channel RxPDO1 (201h) for the whole line, reading one display's state by SDO,
// finding the displays on the bus, and decoding their TxPDOs and EMCYs as they arrive.
//
// Contracts:
// - Commands are unconfirmed PDOs: they return at once; a Result error means nothing was sent
//   (forbidden control word, object not allowed by broadcast, value out of range, bus closed).
// - PDOs are executed by the displays only in NMT Operational; start the nodes first.
// - Replies are owned by the caller and always finish (the SDO client's timeouts).

#include "nm17xdescription.h"
#include "nm17xpdo.h"

#include "canopen/cannetwork.h"
#include "canopen/emcyconsumer.h"
#include "core/reply.h"

#include <QObject>

namespace db::nm17x {

// One display as read by SDO.
struct DisplayState
{
    canopen::NodeId node = 0;
    Variant variant = Variant::Nm170;
    quint32 serial = 0;
    qint32 position = 0; // 6004h, 1/100 mm
    quint16 status = 0; // 204Eh:01 (NM170: 1002h, bit 12 only)
    quint16 errors = 0; // 204Eh:02 (NM170: none)
    bool inch = false; // 2001h

    // "node 3  NM172  serial 0x4D52F567  position 10.00 mm  In Position  errors -"
    QString toString() const;
};

// 1/100 mm as the display shows it: "10.00 mm" or "0.3937 in".
QString formatPosition(qint32 hundredthsMm, bool inch);
// "10", "-2.5", "9999.99" (mm) -> 1/100 mm; InvalidArgument outside -999.99..9999.99 mm.
Result<qint32> parseMillimetres(const QString &text);

// Scaling 2004h (units of 1e-7) for a spindle pitch (1/100 mm per revolution) and the sensor's
// steps per revolution: pitch / steps x 10^7, e.g. 400 and 2304 give 1736111. 0 when steps <= 0.
quint32 scalingFor(qint32 pitchHundredths, int stepsPerRevolution);
// The pitch (1/100 mm per revolution) a scaling stands for.
double pitchOf(quint32 scaling, int stepsPerRevolution);
// The built-in multiturn sensor of NM170/NM172 counts 2304 steps per revolution; for the NM174
// the SSI sensor decides, and 4096 (a common rotary encoder) is the starting value offered.
int stepsPerRevolution(Variant variant);

enum class SetpointKind {
    Standard, // without release: the display shows it, the motor waits for a start
    Release, // the motor starts at once
    Direct, // with release, without loop
    Plunge, // Einsaegen at a speed, without release
    PlungeRelease,
};

class Nm17xLine : public QObject
{
    Q_OBJECT
public:
    // The network is not owned and must outlive the line.
    explicit Nm17xLine(canopen::CanNetwork *network, QObject *parent = nullptr);

    // ---- RxPDO2, one display ----
    // The raw command, sent only when its control word is an allowed combination.
    Result<void> send(canopen::NodeId node, const PositionCommand &command);
    // correction: 16-bit correction (2010h), nullopt keeps 2010h (sends -32768).
    Result<void> setpoint(canopen::NodeId node, qint32 value, SetpointKind kind,
                          std::optional<qint16> correction = {}, std::optional<Speed> speed = {});
    Result<void> jog(canopen::NodeId node, int direction, Speed speed); // +1 right, -1 left
    Result<void> stop(canopen::NodeId node);

    // ---- RxPDO1, every display ----
    Result<void> broadcast(const Broadcast &command); // only the allowed objects
    Result<void> setUnit(bool inch);
    Result<void> showNodeIds(bool show);
    Result<void> startGroup(int group); // 1..8
    Result<void> stopAll();
    Result<void> presetAll(qint32 value);

    // ---- SDO ----
    // Value: QVariant::fromValue(DisplayState). NotSupported when the node is no NM17x.
    Reply *readState(canopen::NodeId node);
    // Every NM17x display on the bus (node ids 1..127 probed at once, about one SDO timeout),
    // sorted by node id. Value: QVariant::fromValue(QList<DisplayState>); nodes of other
    // vendors are left out, displays that fail to answer their state are named in problems().
    Reply *findDisplays();
    QStringList problems() const { return m_problems; }
    // One object of a display, checked first against the display's description (the one its
    // identity chose, else the NM174's, which has every object): a value outside the object's
    // range fails at once, naming the range, and nothing is sent. Value: none.
    Reply *write(canopen::NodeId node, ObjectAddress address, qint64 value);
    // Value: the number as a qlonglong (signed by the object's type).
    Reply *read(canopen::NodeId node, ObjectAddress address);

Q_SIGNALS:
    // Decoded as they arrive, for every node (TxPDO COB-IDs 180h/280h + node).
    void tpdo1(db::canopen::NodeId node, const db::nm17x::Tpdo1 &pdo);
    void tpdo2(db::canopen::NodeId node, const db::nm17x::Tpdo2 &pdo);
    // An EMCY with the display's text for its code and sub-code (byte 7).
    void emergency(db::canopen::NodeId node, quint16 code, quint8 subCode, const QString &text);

private:
    const ObjectDef *definition(canopen::NodeId node, ObjectAddress address) const;
    Result<void> sendFrame(quint32 id, const QByteArray &payload);
    void readNext(Reply *outer, DisplayState state, QList<ObjectAddress> todo);
    void readStates(Reply *outer, QList<canopen::NodeId> todo, QList<DisplayState> done);

    canopen::CanNetwork *m_network;
    QStringList m_problems;
};

} // namespace db::nm17x

Q_DECLARE_METATYPE(db::nm17x::DisplayState)
Q_DECLARE_METATYPE(QList<db::nm17x::DisplayState>)
Q_DECLARE_METATYPE(db::nm17x::Tpdo1)
Q_DECLARE_METATYPE(db::nm17x::Tpdo2)
