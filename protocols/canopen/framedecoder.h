#pragma once

// CANopen reading of single CAN frames for the CAN monitor and logs (CiA 301 7.3.5 predefined
// connection set): which service a frame belongs to, which node, and one line of text such as
//
//   SDO rx node 50: upload 6041:0 Statusword
//   SDO tx node 50: upload 6041:0 Statusword → 0x0427
//   EMCY node 50: 3221 ERROR_UNDER_VOLT (voltage), reg 0x05
//   Heartbeat node 50: operational
//   NMT start node 50
//
// No widgets, no I/O. The decoder keeps a little state on purpose: per node the object of the
// SDO transfer in progress (so that segments name their object, as SDO segments carry no
// multiplexer) and, optionally, per node a dictionary for object names, value formats and
// EMCY texts. "rx"/"tx" in SDO texts are the server's view (CiA 301: RSDO 600h+n, TSDO 580h+n),
// independent of the frame's direction on our bus.

#include "canopenids.h"
#include "core/objectdictionary.h"

#include <QCanBusFrame>
#include <QHash>

namespace db::canopen {

enum class Service {
    Nmt,
    Sync,
    Emcy,
    Time,
    Tpdo, // pdoNumber 1..4
    Rpdo,
    SdoRequest, // client -> server, 600h + node
    SdoResponse, // server -> client, 580h + node
    Heartbeat, // NMT error control, 700h + node, state != 0
    BootUp, // 700h + node with 00h
    Lss, // 7E4h / 7E5h
    Other, // extended frames, error frames, unassigned ids
};

struct DecodedFrame
{
    Service service = Service::Other;
    NodeId node = 0; // 0: none (SYNC, TIME, LSS) or every node (NMT broadcast)
    int pdoNumber = 0; // 1..4 for TPDO/RPDO
    bool hasAddress = false; // SDO frames whose object is known (initiate, abort, segments)
    ObjectAddress address;
    QString text;
    // text without the "SDO tx node 50: " head, for tables that show service and node apart
    QString detail;
};

class FrameDecoder
{
public:
    // Names, value formats and EMCY texts for one node; nodes without one are decoded by
    // CiA 301 alone.
    void setDictionary(NodeId node, const ObjectDictionary &dictionary);
    void removeDictionary(NodeId node);
    const ObjectDictionary *dictionary(NodeId node) const;
    // Forgets the SDO transfers in progress (dictionaries stay).
    void reset();

    // The reading does not depend on who sent the frame: the COB-ID says it (CiA 301 7.3.5).
    DecodedFrame decode(const QCanBusFrame &frame);

    // "SDO", "TPDO", "Heartbeat", ... (short, for a table column).
    static QString serviceName(Service service, int pdoNumber = 0);

private:
    QString objectText(NodeId node, ObjectAddress address) const;
    QString valueText(NodeId node, ObjectAddress address, const QByteArray &bytes) const;
    void decodeSdo(DecodedFrame &out, const QByteArray &data, bool request);
    void decodeSdoRequest(DecodedFrame &out, const QByteArray &data);
    void decodeSdoResponse(DecodedFrame &out, const QByteArray &data);
    void decodeEmcy(DecodedFrame &out, const QByteArray &data) const;
    void decodePdo(DecodedFrame &out, const QByteArray &data) const;
    void decodeNmt(DecodedFrame &out, const QByteArray &data) const;

    // The object of the SDO transfer in progress per node, and whether it is a block transfer
    // (block segments have no command specifier).
    struct Transfer
    {
        ObjectAddress address;
        bool upload = true;
        bool block = false;
        bool blockData = false; // block segments are flowing
        bool lastSegment = false; // the segment with c = 1 has been seen
    };
    QHash<NodeId, Transfer> m_transfers;
    QHash<NodeId, ObjectDictionary> m_dictionaries;
};

// "4B 41 60 00 27 04 00 00" (upper case, spaced).
QString hexBytes(const QByteArray &bytes);

} // namespace db::canopen
