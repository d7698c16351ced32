#include "framedecoder.h"

#include "emcyconsumer.h"
#include "nmtmaster.h"
#include "sdocodec.h"

#include <QCoreApplication>
#include <QDateTime>

namespace db::canopen {

namespace {

// The monitor's texts are for people: their words are translated, CANopen's own terms (NMT,
// SDO, TPDO1, blksize, crc) and the numbers stay as they are.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen::FrameDecoder)
};

QString hex2(int value)
{
    return QStringLiteral("0x%1")
        .arg(value, 2, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QStringLiteral("0X"), QStringLiteral("0x"));
}

QString nodeText(NodeId node)
{
    return node == 0 ? Tr::tr("all nodes") : Tr::tr("node %1").arg(node);
}

// NMT command specifiers (CiA 301 7.2.8.3.1) as short verbs: "NMT start node 50".
QString nmtVerb(quint8 command)
{
    switch (NmtCommand(command)) {
    case NmtCommand::Start:
        return Tr::tr("start");
    case NmtCommand::Stop:
        return Tr::tr("stop");
    case NmtCommand::EnterPreOperational:
        return Tr::tr("pre-operational");
    case NmtCommand::ResetNode:
        return Tr::tr("reset");
    case NmtCommand::ResetCommunication:
        return Tr::tr("reset communication");
    }
    return Tr::tr("command %1").arg(hex2(command));
}

// LSS command specifiers (CiA 305 4.x), byte 0 of 7E5h/7E4h.
QString lssCommand(quint8 cs)
{
    switch (cs) {
    case 0x04:
        return Tr::tr("switch state global");
    case 0x11:
        return Tr::tr("configure node-id");
    case 0x13:
        return Tr::tr("configure bit timing");
    case 0x15:
        return Tr::tr("activate bit timing");
    case 0x17:
        return Tr::tr("store configuration");
    case 0x40:
    case 0x41:
    case 0x42:
    case 0x43:
        return Tr::tr("switch state selective");
    case 0x44:
        return Tr::tr("switch state selective response");
    case 0x4F:
        return Tr::tr("identify non-configured");
    case 0x50:
        return Tr::tr("identify slave");
    case 0x51:
        return Tr::tr("fastscan");
    case 0x5A:
        return Tr::tr("inquire vendor-id");
    case 0x5B:
        return Tr::tr("inquire product code");
    case 0x5C:
        return Tr::tr("inquire revision");
    case 0x5D:
        return Tr::tr("inquire serial number");
    case 0x5E:
        return Tr::tr("inquire node-id");
    }
    return Tr::tr("command %1").arg(hex2(cs));
}

// TIME_OF_DAY (CiA 301 7.1.6.5): 28 bits ms after midnight, 16 bits days since 1984-01-01.
QString timeOfDay(const QByteArray &data)
{
    if (data.size() < 6)
        return Tr::tr("TIME (%1 bytes)").arg(data.size());
    const quint32 ms = sdocodec::u32(data, 0) & 0x0FFFFFFF;
    const int days = sdocodec::byteAt(data, 4) | (sdocodec::byteAt(data, 5) << 8);
    const QDateTime t(QDate(1984, 1, 1).addDays(days), QTime(0, 0).addMSecs(int(ms)), Qt::UTC);
    return QStringLiteral("TIME %1").arg(t.toString(QStringLiteral("yyyy-MM-dd hh:mm:ss.zzz")));
}

// The main class of an emergency error code (CiA 301 table 21, first digit), short enough for a
// monitor line; emcy::decode() has the finer sub-classes.
QString errorMainClass(quint16 code)
{
    if ((code & 0xFF00) == 0xFF00)
        return Tr::tr("device specific");
    if ((code & 0xFF00) == 0xF000)
        return Tr::tr("additional functions");
    static const char *const classes[16] = {
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "error reset"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "generic"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "current"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "voltage"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "temperature"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "device hardware"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "device software"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "additional modules"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "monitoring"),
        QT_TRANSLATE_NOOP("db::canopen::FrameDecoder", "external error"),
        "class A",
        "class B",
        "class C",
        "class D",
        "class E",
        "class F",
    };
    return Tr::tr(classes[code >> 12]);
}

} // namespace

QString hexBytes(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ')).toUpper();
}

void FrameDecoder::setDictionary(NodeId node, const ObjectDictionary &dictionary)
{
    m_dictionaries.insert(node, dictionary);
}

void FrameDecoder::removeDictionary(NodeId node)
{
    m_dictionaries.remove(node);
}

const ObjectDictionary *FrameDecoder::dictionary(NodeId node) const
{
    const auto it = m_dictionaries.constFind(node);
    return it == m_dictionaries.cend() ? nullptr : &*it;
}

void FrameDecoder::reset()
{
    m_transfers.clear();
}

QString FrameDecoder::serviceName(Service service, int pdoNumber)
{
    switch (service) {
    case Service::Nmt:
        return QStringLiteral("NMT");
    case Service::Sync:
        return QStringLiteral("SYNC");
    case Service::Emcy:
        return QStringLiteral("EMCY");
    case Service::Time:
        return QStringLiteral("TIME");
    case Service::Tpdo:
        return QStringLiteral("TPDO%1").arg(pdoNumber);
    case Service::Rpdo:
        return QStringLiteral("RPDO%1").arg(pdoNumber);
    case Service::SdoRequest:
        return QStringLiteral("SDO rx");
    case Service::SdoResponse:
        return QStringLiteral("SDO tx");
    case Service::Heartbeat:
        return QStringLiteral("Heartbeat");
    case Service::BootUp:
        return QStringLiteral("Boot-up");
    case Service::Lss:
        return QStringLiteral("LSS");
    case Service::Other:
        break;
    }
    return QString();
}

DecodedFrame FrameDecoder::decode(const QCanBusFrame &frame)
{
    DecodedFrame out;
    const QByteArray data = frame.payload();
    if (frame.frameType() == QCanBusFrame::ErrorFrame) {
        out.text = Tr::tr("error frame");
        return out;
    }
    if (frame.hasExtendedFrameFormat()) {
        out.text = Tr::tr("extended frame (not CANopen)");
        return out;
    }
    const bool remote = frame.frameType() == QCanBusFrame::RemoteRequestFrame;
    const quint32 id = frame.frameId();
    const quint32 function = id & 0x780;
    const NodeId node = NodeId(id & 0x7F);

    if (id == cob::Nmt) {
        decodeNmt(out, data);
    } else if (id == cob::Sync) {
        out.service = Service::Sync;
        out.text = data.isEmpty() ? QStringLiteral("SYNC")
                                  : Tr::tr("SYNC counter %1").arg(quint8(data.at(0)));
    } else if (function == cob::EmcyBase && node != 0) {
        out.service = Service::Emcy;
        out.node = node;
        decodeEmcy(out, data);
    } else if (id == cob::Time) {
        out.service = Service::Time;
        out.text = timeOfDay(data);
    } else if (function >= cob::Tpdo1 && function <= cob::Rpdo4 && node != 0) {
        // 180h/200h, 280h/300h, 380h/400h, 480h/500h: odd steps of 80h are TPDOs.
        const int step = int(function >> 7) - 3; // 0..7
        out.service = step % 2 == 0 ? Service::Tpdo : Service::Rpdo;
        out.pdoNumber = step / 2 + 1;
        out.node = node;
        if (remote)
            out.text = Tr::tr("%1 node %2: remote request")
                           .arg(serviceName(out.service, out.pdoNumber))
                           .arg(node);
        else
            decodePdo(out, data);
    } else if ((function == cob::SdoTx || function == cob::SdoRx) && node != 0) {
        out.node = node;
        decodeSdo(out, data, function == cob::SdoRx);
    } else if (function == cob::Heartbeat && node != 0) {
        out.node = node;
        out.service = Service::Heartbeat;
        if (remote) {
            out.text = Tr::tr("Node guarding request node %1").arg(node);
        } else if (data.isEmpty()) {
            out.text = Tr::tr("Heartbeat node %1: no data").arg(node);
        } else {
            const quint8 state = quint8(data.at(0)) & 0x7F; // bit 7: node guarding toggle
            if (state == quint8(NmtState::BootUp)) {
                out.service = Service::BootUp;
                out.text = Tr::tr("Boot-up node %1").arg(node);
            } else {
                const QString name = nmtStateName(NmtState(state));
                out.text = Tr::tr("Heartbeat node %1: %2").arg(node).arg(name);
            }
        }
    } else if (id == cob::LssMaster || id == cob::LssSlave) {
        out.service = Service::Lss;
        out.text = (id == cob::LssMaster ? Tr::tr("LSS master: %1") : Tr::tr("LSS slave: %1"))
                       .arg(data.isEmpty() ? Tr::tr("no data") : lssCommand(quint8(data.at(0))));
    }
    const qsizetype colon = out.text.indexOf(QLatin1String(": "));
    out.detail = colon > 0 ? out.text.mid(colon + 2) : out.text;
    return out;
}

void FrameDecoder::decodeNmt(DecodedFrame &out, const QByteArray &data) const
{
    out.service = Service::Nmt;
    if (data.size() < 2) {
        out.text = Tr::tr("NMT malformed (%1 bytes)").arg(data.size());
        return;
    }
    out.node = NodeId(quint8(data.at(1)));
    out.text = QStringLiteral("NMT %1 %2").arg(nmtVerb(quint8(data.at(0))), nodeText(out.node));
}

void FrameDecoder::decodeEmcy(DecodedFrame &out, const QByteArray &data) const
{
    const ObjectDictionary *dict = dictionary(out.node);
    const auto decoded = emcy::decode(out.node, data, dict);
    if (!decoded) {
        out.text = Tr::tr("EMCY node %1: malformed (%2 bytes)").arg(out.node).arg(data.size());
        return;
    }
    const Emergency &e = decoded.value();
    QString code = QStringLiteral("%1").arg(e.code, 4, 16, QLatin1Char('0')).toUpper();
    if (e.isReset()) {
        code += QLatin1Char(' ') + Tr::tr("error reset");
    } else {
        const auto def = dict ? dict->errorCode(e.code) : std::nullopt;
        if (def && !def->name.isEmpty())
            code += QLatin1Char(' ') + def->name;
        code += QStringLiteral(" (%1)").arg(errorMainClass(e.code));
    }
    out.text = Tr::tr("EMCY node %1: %2, reg %3").arg(out.node).arg(code, hex2(e.errorRegister));
    if (e.manufacturer.count('\0') != e.manufacturer.size())
        out.text += Tr::tr(", data %1").arg(hexBytes(e.manufacturer));
}

// PDO content from the mapping parameters in the node's dictionary (1600h/1A00h + n - 1, their
// default values; CiA 301 7.5.2.36/38: index << 16 | sub << 8 | length in bits).
void FrameDecoder::decodePdo(DecodedFrame &out, const QByteArray &data) const
{
    const QString head =
        Tr::tr("%1 node %2").arg(serviceName(out.service, out.pdoNumber)).arg(out.node);
    QStringList parts;
    if (const ObjectDictionary *dict = dictionary(out.node)) {
        const quint16 mapping =
            quint16((out.service == Service::Tpdo ? 0x1A00 : 0x1600) + out.pdoNumber - 1);
        const ObjectDef *count = dict->find({ mapping, 0 });
        const int entries = count ? count->defaultValue.toInt() : 0;
        int bit = 0;
        for (int sub = 1; sub <= entries && sub <= 64; ++sub) {
            const ObjectDef *entry = dict->find({ mapping, quint8(sub) });
            const quint32 value = entry ? entry->defaultValue.toUInt() : 0;
            const ObjectAddress address(quint16(value >> 16), quint8(value >> 8));
            const int bits = int(value & 0xFF);
            if (bits == 0 || bits % 8 != 0 || bit % 8 != 0 || (bit + bits) / 8 > data.size())
                break; // bit-packed or short frame: leave it to the hex column
            const QByteArray bytes = data.mid(bit / 8, bits / 8);
            parts.append(objectText(out.node, address) + QStringLiteral(" = ")
                         + valueText(out.node, address, bytes));
            bit += bits;
        }
    }
    out.text = parts.isEmpty() ? Tr::tr("%1: %2 bytes").arg(head).arg(data.size())
                               : head + QStringLiteral(": ") + parts.join(QStringLiteral(", "));
}

QString FrameDecoder::objectText(NodeId node, ObjectAddress address) const
{
    const ObjectDictionary *dict = dictionary(node);
    const ObjectDef *def = dict ? dict->find(address) : nullptr;
    if (!def)
        return address.toString();
    const QString name = def->objectName.isEmpty() || def->objectName == def->name
        ? def->displayName()
        : def->displayObjectName() + QStringLiteral(" / ") + def->displayName();
    return address.toString() + QLatin1Char(' ') + name;
}

// Integers without unit or enumeration read best in hex (status and control words); everything
// else as the object displays it. Unknown objects: hex of the bytes as an integer.
QString FrameDecoder::valueText(NodeId node, ObjectAddress address, const QByteArray &bytes) const
{
    const ObjectDictionary *dict = dictionary(node);
    if (const ObjectDef *def = dict ? dict->find(address) : nullptr) {
        if (const auto raw = codec::decode(def->type, bytes)) {
            const bool plain = datatype::isInteger(def->type) && def->unit.isEmpty()
                && def->enumeration.isEmpty() && def->factor == 1.0 && def->offset == 0.0;
            const bool isUnsigned = raw.value().typeId() == QMetaType::ULongLong;
            return def->localDisplayText(raw.value(),
                                         plain && isUnsigned ? codec::TextFormat::Hex
                                                             : codec::TextFormat::Decimal);
        }
    }
    if (bytes.isEmpty() || bytes.size() > 8)
        return hexBytes(bytes);
    quint64 value = 0;
    for (int i = bytes.size() - 1; i >= 0; --i)
        value = (value << 8) | quint8(bytes.at(i));
    return QStringLiteral("0x%1")
        .arg(value, bytes.size() * 2, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QStringLiteral("0X"), QStringLiteral("0x"));
}

} // namespace db::canopen
