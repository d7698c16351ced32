#pragma once

// CiA 301 identifiers shared by the master services and the device side (simulated nodes).
// Pure constants and tiny helpers; no state.

#include <QtGlobal>

namespace db::canopen {

using NodeId = quint8; // 1..127; 0 = broadcast in NMT

constexpr NodeId kMinNodeId = 1;
constexpr NodeId kMaxNodeId = 127;

// Predefined connection set (CiA 301 7.3.5): function code + node id.
namespace cob {
constexpr quint32 Nmt = 0x000;
constexpr quint32 Sync = 0x080;
constexpr quint32 EmcyBase = 0x080; // + node id (0x081..0x0FF)
constexpr quint32 Time = 0x100;
constexpr quint32 Tpdo1 = 0x180;
constexpr quint32 Rpdo1 = 0x200;
constexpr quint32 Tpdo2 = 0x280;
constexpr quint32 Rpdo2 = 0x300;
constexpr quint32 Tpdo3 = 0x380;
constexpr quint32 Rpdo3 = 0x400;
constexpr quint32 Tpdo4 = 0x480;
constexpr quint32 Rpdo4 = 0x500;
constexpr quint32 SdoTx = 0x580; // server -> client, + node id
constexpr quint32 SdoRx = 0x600; // client -> server, + node id
constexpr quint32 Heartbeat = 0x700; // + node id (NMT error control, boot-up)
constexpr quint32 LssMaster = 0x7E5;
constexpr quint32 LssSlave = 0x7E4;

constexpr quint32 emcy(NodeId node)
{
    return EmcyBase + node;
}
constexpr quint32 sdoRequest(NodeId node)
{
    return SdoRx + node;
}
constexpr quint32 sdoResponse(NodeId node)
{
    return SdoTx + node;
}
constexpr quint32 heartbeat(NodeId node)
{
    return Heartbeat + node;
}
} // namespace cob

// NMT command specifiers (CiA 301 7.2.8.3.1), byte 0 of COB 0x000; byte 1 = node id or 0.
enum class NmtCommand : quint8 {
    Start = 0x01,
    Stop = 0x02,
    EnterPreOperational = 0x80,
    ResetNode = 0x81,
    ResetCommunication = 0x82,
};

// NMT states as reported in heartbeat byte 0 (CiA 301 7.2.8.3.2).
enum class NmtState : quint8 {
    BootUp = 0x00,
    Stopped = 0x04,
    Operational = 0x05,
    PreOperational = 0x7F,
    Unknown = 0xFF, // not a wire value: nothing heard yet
};

// SDO command specifier bits (CiA 301 7.2.4.3): client command specifier in bits 7..5.
namespace sdo {
constexpr quint8 CcsDownloadSegment = 0;
constexpr quint8 CcsInitiateDownload = 1;
constexpr quint8 CcsInitiateUpload = 2;
constexpr quint8 CcsUploadSegment = 3;
constexpr quint8 CcsAbort = 4;
constexpr quint8 CcsBlockUpload = 5;
constexpr quint8 CcsBlockDownload = 6;

constexpr quint8 ScsUploadSegment = 0;
constexpr quint8 ScsDownloadSegment = 1;
constexpr quint8 ScsInitiateUpload = 2;
constexpr quint8 ScsInitiateDownload = 3;
constexpr quint8 ScsAbort = 4;
constexpr quint8 ScsBlockDownload = 5;
constexpr quint8 ScsBlockUpload = 6;

constexpr quint8 AbortByte = 0x80;
constexpr int kMaxBlockSize = 127; // segments per block
} // namespace sdo

} // namespace db::canopen
