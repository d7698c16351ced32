#pragma once
// Passive sampling of CANopen PDOs on a bus, and the opt-in TPDO set-up helper.
#include "canopen/canopenids.h"
#include "canopen/pdomapping.h"
#include "core/datatype.h"
#include "core/reply.h"
#include "tracesource.h"
#include <QCanBusFrame>
#include <QHash>
#include <QPointer>
#include <optional>

namespace db {
class CanBus;
class DeviceConnection;
namespace canopen {
class PdoClient;
} // namespace canopen
} // namespace db

namespace db::scope {

// Listens to the frames of a CanBus and turns bytes of chosen PDOs into samples.
//
// PASSIVE: it sends nothing, so it changes neither the device's PDO configuration nor its NMT
// state; the PDOs must already be transmitted (configured by the device, a PLC, or by
// configureTpdo() below on explicit request). A channel is (COB-ID, byte offset, type):
// little-endian as CiA 301 7.2.2, length given by the type (1..8 bytes; booleans one byte).
// Timestamps: the time base's elapsed time when the frame is received by this process.
// Loss: a PDO shorter than offset+length counts a lost sample for the channels it cannot fill
// (Malformed data never stops the source); the bus closing stops the source with
// errorOccurred(). A channel with expectedPeriodMs > 0 also counts a lost sample (and a gap)
// for every missed period: a gap between two frames of more than 1.5 periods counts
// round(gap/period) - 1 lost samples. Remote frames and error frames are ignored.
class PdoSource : public TraceSource
{
    Q_OBJECT
public:
    struct Mapping
    {
        quint32 cobId = 0; // 11-bit CAN id (29-bit when > 0x7FF)
        int byteOffset = 0; // 0..7
        DataType type = DataType::Integer32; // integer, boolean or Real32/Real64
        int expectedPeriodMs = 0; // 0 = event driven: no loss detection by time
    };

    // The bus is not owned and must outlive the source.
    explicit PdoSource(CanBus *bus, QObject *parent = nullptr);
    // Listens on the bus of the connection's CAN network (none for other protocols); device URI
    // from the connection.
    explicit PdoSource(DeviceConnection *connection, QObject *parent = nullptr);
    ~PdoSource() override;

    // InvalidArgument when running, offset+size > 8, or the type is not numeric.
    Result<int> addChannel(const ChannelInfo &info, const Mapping &mapping);
    // One channel per mapped object of an (enabled) TPDO configuration, in mapping order, with
    // names/units/scaling from `dictionary`; entries that do not fall on a byte boundary or are
    // dummies are skipped. Returns the channel indices.
    Result<QList<int>> addPdo(const canopen::PdoConfig &config, const ObjectDictionary &dictionary,
                              const QString &device, int expectedPeriodMs = 0);
    void removeChannel(int channel); // only while stopped
    Mapping mapping(int channel) const;

    QList<ChannelInfo> channels() const override;
    bool isRunning() const override { return m_running; }
    void start(const QElapsedTimer &timeBase) override;
    void stop() override;

    qint64 framesSeen() const { return m_frames; }

    // Pure decode of one channel's value from a PDO payload (little-endian); nullopt when the
    // payload is too short.
    static std::optional<double> decodeValue(const QByteArray &payload, const Mapping &mapping);

private:
    struct Entry
    {
        ChannelInfo info;
        Mapping mapping;
        double lastTime = -1; // seconds; < 0 = no frame yet since start()
    };
    void onFrame(const QCanBusFrame &frame);
    void onBusClosed(const Error &error);

    QPointer<CanBus> m_bus;
    QString m_device;
    QList<Entry> m_entries;
    QHash<quint32, QList<int>> m_byCobId;
    QElapsedTimer m_timeBase;
    bool m_running = false;
    qint64 m_frames = 0;
};

// OPT-IN, separate from PdoSource: writes a TPDO configuration so that the node sends `objects`
// (mapped in order; at most 64 bits in total) on `cobId` (0 = the predefined 0x180 + 0x100 *
// (number % 4) + node for TPDO1..4), with transmission type 0xFF (event driven, "asynchronous")
// and the event timer `eventTimerMs`. Types/sizes come from `dictionary` (objects it does not
// know are rejected). The reply (caller owns it) finishes with QVariant::fromValue(PdoConfig) of
// the configuration written, or the first SDO error. This DOES change the device's PDO
// configuration (RAM only; nothing is stored); the NMT state is untouched (PDOs are only sent
// in Operational).
Reply *configureTpdo(canopen::PdoClient *client, canopen::NodeId node, int tpdoNumber,
                     const QList<ObjectAddress> &objects, const ObjectDictionary &dictionary,
                     int eventTimerMs, quint32 cobId = 0);
// The configuration configureTpdo() writes (pure; InvalidArgument when an object is unknown or
// not mappable as a whole number of bytes, or the total exceeds 64 bits).
Result<canopen::PdoConfig> tpdoConfigFor(canopen::NodeId node, int tpdoNumber,
                                         const QList<ObjectAddress> &objects,
                                         const ObjectDictionary &dictionary, int eventTimerMs,
                                         quint32 cobId = 0);

} // namespace db::scope
