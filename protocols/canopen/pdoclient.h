#pragma once

// Reads and writes a node's PDO configuration through SDO (CiA 301 7.5.2.35-7.5.2.38).
//
// Contracts:
// - Every call returns a Reply the caller owns; it always finishes (the SDO client's timeouts
//   bound every step). Errors name the object that failed ("writing 1A00:1: ...").
// - configure() follows the CiA 301 7.5.2.36 order, so the device never runs a half-written
//   mapping:
//     disable (COB-ID | bit 31) -> [transmission type, inhibit, event timer]
//       -> mapping sub 0 = 0 -> entries 1..n -> sub 0 = n -> COB-ID as configured
//   The first failing step ends the sequence; the PDO then stays disabled.
// - The SDO client is not owned and must outlive this object.

#include "canopenids.h"
#include "core/reply.h"
#include "pdomapping.h"

#include <functional>
#include <optional>

namespace db::canopen {

class SdoClient;

class PdoClient : public QObject
{
    Q_OBJECT
public:
    // One SDO download of the configure sequence.
    struct Write
    {
        ObjectAddress address;
        QByteArray data;
    };

    explicit PdoClient(SdoClient *sdo, QObject *parent = nullptr);

    // Reply value: QVariant::fromValue(PdoConfig). A PDO the device does not have fails with the
    // device's abort (DeviceError, 06020000h "object does not exist").
    Reply *read(NodeId node, PdoDirection direction, int number);
    // Reply value: QVariant::fromValue(QList<PdoConfig>), RPDOs then TPDOs (only those of
    // direction `only` when given). The numbers read are those `dictionary` describes; without
    // any, each direction is read from 1 on up to the first missing communication object.
    Reply *readAll(NodeId node, const ObjectDictionary &dictionary = {},
                   std::optional<PdoDirection> only = std::nullopt);
    // Writes `config` (comm + mapping) in the safe order above. Reply without value.
    Reply *configure(NodeId node, const PdoConfig &config);

    // The downloads configure() makes, in order (pure; for tests and dry runs).
    static QList<Write> configureSequence(const PdoConfig &config);

private:
    using Then = std::function<void(const Result<QByteArray> &)>;
    void step(Reply *outer, Reply *inner, Then then);
    void readMapping(NodeId node, Reply *outer, PdoConfig config, int count);
    void readNext(NodeId node, Reply *outer, QList<PdoConfig> done, QList<PdoConfig> todo,
                  bool probing);
    void runWrites(NodeId node, Reply *outer, QList<Write> writes);

    SdoClient *m_sdo;
};

} // namespace db::canopen
