#include "emcyconsumer.h"

#include "canopenlogging.h"
#include "transport/canbus.h"

#include <QCanBusFrame>
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};
} // namespace

namespace db::canopen {

namespace emcy {

QStringList errorRegisterBits(quint8 reg)
{
    static const char *const names[8] = {
        "generic",       "current",
        "voltage",       "temperature",
        "communication", "device profile specific",
        "reserved",      "manufacturer specific",
    };
    QStringList bits;
    for (int bit = 0; bit < 8; ++bit) {
        if (reg & (1u << bit))
            bits.append(QString::fromLatin1(names[bit]));
    }
    return bits;
}

Result<Emergency> decode(NodeId node, const QByteArray &payload, const ObjectDictionary *dictionary)
{
    if (payload.size() < 3)
        return Error(Error::Kind::Malformed,
                     Tr::tr("EMCY from node %1 has %2 bytes, needs at least 3")
                         .arg(node)
                         .arg(payload.size()));
    Emergency e;
    e.node = node;
    e.code = quint16(quint8(payload.at(0)) | (quint8(payload.at(1)) << 8));
    e.errorRegister = quint8(payload.at(2));
    e.manufacturer = payload.mid(3, 5);
    e.manufacturer.append(QByteArray(5 - e.manufacturer.size(), '\0'));
    e.errorClass = cia301ErrorClassText(e.code);
    e.text = dictionary ? dictionary->errorText(e.code) : e.errorClass;
    return e;
}

} // namespace emcy

QString Emergency::toString() const
{
    QString s = QStringLiteral("node %1 EMCY %2h: %3")
                    .arg(node)
                    .arg(code, 4, 16, QLatin1Char('0'))
                    .arg(text);
    if (!errorClass.isEmpty() && errorClass != text)
        s += QStringLiteral(" [%1]").arg(errorClass);
    s += QStringLiteral(", error register %1h").arg(errorRegister, 2, 16, QLatin1Char('0'));
    const QStringList bits = emcy::errorRegisterBits(errorRegister);
    if (!bits.isEmpty())
        s += QStringLiteral(" (%1)").arg(bits.join(QStringLiteral(", ")));
    if (manufacturer.count('\0') != manufacturer.size())
        s += QStringLiteral(", manufacturer data %1")
                 .arg(QString::fromLatin1(manufacturer.toHex(' ')).toUpper());
    return s;
}

EmcyConsumer::EmcyConsumer(CanBus *bus, QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<db::canopen::Emergency>();
    connect(bus, &CanBus::frameReceived, this, &EmcyConsumer::onFrame);
}

void EmcyConsumer::setDictionary(NodeId node, const ObjectDictionary &dictionary)
{
    m_dictionaries.insert(node, dictionary);
}

void EmcyConsumer::onFrame(const QCanBusFrame &frame)
{
    const quint32 id = frame.frameId();
    // 080h itself is SYNC.
    if (frame.frameType() != QCanBusFrame::DataFrame || frame.hasExtendedFrameFormat()
        || id <= cob::EmcyBase || id > cob::EmcyBase + kMaxNodeId)
        return;
    const NodeId node = NodeId(id - cob::EmcyBase);
    const auto it = m_dictionaries.constFind(node);
    auto decoded =
        emcy::decode(node, frame.payload(), it != m_dictionaries.cend() ? &it.value() : nullptr);
    if (!decoded) {
        qCWarning(lcCanopen).noquote() << decoded.error().message();
        Q_EMIT malformed(node, frame.payload());
        return;
    }
    Emergency e = decoded.value();
    e.time = QDateTime::currentDateTime();
    qCInfo(lcCanopen).noquote() << e.toString();
    Q_EMIT emergency(e);
}

} // namespace db::canopen
