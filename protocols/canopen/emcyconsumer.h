#pragma once

// EMCY consumer (CiA 301 7.2.7): decodes emergency frames on 081h..0FFh into error code, CiA 301
// class, the device's own text (from its ObjectDictionary), error register bits and the five
// manufacturer bytes.

#include "canopenids.h"
#include "core/objectdictionary.h"

#include <QDateTime>
#include <QObject>

class QCanBusFrame;

namespace db {
class CanBus;
}

namespace db::canopen {

struct Emergency
{
    NodeId node = 0;
    quint16 code = 0; // bytes 0..1, little-endian
    quint8 errorRegister = 0; // byte 2 (object 1001h)
    QByteArray manufacturer; // bytes 3..7, as sent (zero-padded to 5 bytes)
    QString text; // the device's text for the code, else the CiA 301 class
    QString errorClass; // CiA 301 table 21 class ("voltage")
    QDateTime time; // when it was received (invalid for decode() results)

    bool isReset() const { return code == 0; } // "error reset / no error"
    // "node 50 EMCY 3221h: under-voltage ... [voltage] register 05h (generic, voltage)"
    QString toString() const;
};

namespace emcy {
// Names of the error register bits set in `reg` (CiA 301 7.5.2.2): "generic", "current", ...
QStringList errorRegisterBits(quint8 reg);
// Pure: a payload of at least 3 bytes; Malformed for shorter ones. dictionary may be null.
Result<Emergency> decode(NodeId node, const QByteArray &payload,
                         const ObjectDictionary *dictionary = nullptr);
} // namespace emcy

class EmcyConsumer : public QObject
{
    Q_OBJECT
public:
    // The bus is not owned and must outlive the consumer.
    explicit EmcyConsumer(CanBus *bus, QObject *parent = nullptr);

    // Texts for one node's codes (its device description). Others get CiA 301 classes only.
    void setDictionary(NodeId node, const ObjectDictionary &dictionary);

Q_SIGNALS:
    void emergency(const db::canopen::Emergency &emcy);
    // An EMCY frame too short to decode (logged, never thrown away silently).
    void malformed(db::canopen::NodeId node, const QByteArray &payload);

private:
    void onFrame(const QCanBusFrame &frame);

    QHash<NodeId, ObjectDictionary> m_dictionaries;
};

} // namespace db::canopen

Q_DECLARE_METATYPE(db::canopen::Emergency)
