#include "nm17xline.h"

#include "nm17xcodes.h"

#include "canopen/nodescanner.h"
#include "canopen/sdoclient.h"
#include "core/valuecodec.h"

#include <QCoreApplication>
#include <QtEndian>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(Nm17x)
};
} // namespace

namespace db::nm17x {

using namespace db::canopen;

namespace {
constexpr double kMmPerInch = 25.4;
} // namespace

QString formatPosition(qint32 v, bool inch)
{
    if (inch)
        return QStringLiteral("%1 in").arg(v / 100.0 / kMmPerInch, 0, 'f', 4);
    return QStringLiteral("%1 mm").arg(v / 100.0, 0, 'f', 2);
}

Result<qint32> parseMillimetres(const QString &text)
{
    bool ok = false;
    const double mm = text.toDouble(&ok);
    const double hundredths = mm * 100.0;
    if (!ok || hundredths < kMinPosition - 0.5 || hundredths > kMaxPosition + 0.5)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("'%1' is not a position in mm (-999.99 .. 9999.99)").arg(text));
    return qint32(qRound(hundredths));
}

quint32 scalingFor(qint32 pitchHundredths, int stepsPerRevolution)
{
    if (stepsPerRevolution <= 0 || pitchHundredths <= 0)
        return 0;
    return quint32(qRound64(double(pitchHundredths) / stepsPerRevolution * 1e7));
}

double pitchOf(quint32 scaling, int stepsPerRevolution)
{
    return double(scaling) * stepsPerRevolution / 1e7;
}

int stepsPerRevolution(Variant variant)
{
    return variant == Variant::Nm174 ? 4096 : 2304;
}

QString DisplayState::toString() const
{
    const QString errorsText = errorText(errors);
    return QStringLiteral("node %1  %2  serial 0x%3  position %4  status %5  errors %6")
        .arg(node, 3)
        .arg(variantName(variant))
        .arg(QString::number(serial, 16).toUpper().rightJustified(8, QLatin1Char('0')))
        .arg(formatPosition(position, inch))
        .arg(statusText(status))
        .arg(errorsText.isEmpty() ? QStringLiteral("-") : errorsText);
}

Nm17xLine::Nm17xLine(CanNetwork *network, QObject *parent)
    : QObject(parent)
    , m_network(network)
{
    for (NodeId node = kMinNodeId; node <= kMaxNodeId; ++node) {
        network->subscribe(cob::Tpdo1 + node, this, [this, node](const QCanBusFrame &f) {
            if (const auto pdo = decodeTpdo1(f.payload()))
                Q_EMIT tpdo1(node, pdo.value());
        });
        network->subscribe(cob::Tpdo2 + node, this, [this, node](const QCanBusFrame &f) {
            if (const auto pdo = decodeTpdo2(f.payload()))
                Q_EMIT tpdo2(node, pdo.value());
        });
        network->subscribe(cob::emcy(node), this, [this, node](const QCanBusFrame &f) {
            const QByteArray d = f.payload();
            if (d.size() < 3)
                return;
            const quint16 code = qFromLittleEndian<quint16>(d.constData());
            const quint8 sub = d.size() >= 8 ? quint8(d.at(7)) : 0;
            const QString text = emcyText(code, sub);
            Q_EMIT emergency(node, code, sub, text.isEmpty() ? cia301ErrorClassText(code) : text);
        });
    }
}

Result<void> Nm17xLine::sendFrame(quint32 id, const QByteArray &payload)
{
    if (!m_network->send(QCanBusFrame(id, payload)))
        return Error(Error::Kind::Disconnected,
                     Tr::tr("the CAN bus %1 is not open").arg(m_network->name()));
    return {};
}

Result<void> Nm17xLine::send(NodeId node, const PositionCommand &command)
{
    if (node < kMinNodeId || node > kMaxNodeId)
        return Error(Error::Kind::InvalidArgument, Tr::tr("node %1 is not 1..127").arg(node));
    if (auto allowed = classify(command.control); !allowed)
        return allowed.error(); // refused here, before it leaves
    if (command.setpoint < kMinPosition || command.setpoint > kMaxPosition)
        return Error(
            Error::Kind::InvalidArgument,
            Tr::tr("setpoint %1 is outside -99999..999999 (1/100 mm)").arg(command.setpoint));
    return sendFrame(cob::Rpdo2 + node, encodePositionCommand(command));
}

Result<void> Nm17xLine::setpoint(NodeId node, qint32 value, SetpointKind kind,
                                 std::optional<qint16> correction, std::optional<Speed> speed)
{
    Command command = Command::Setpoint;
    switch (kind) {
    case SetpointKind::Standard:
        break;
    case SetpointKind::Release:
        command = Command::SetpointRelease;
        break;
    case SetpointKind::Direct:
        command = Command::SetpointDirect;
        break;
    case SetpointKind::Plunge:
        command = Command::Einsaegen;
        break;
    case SetpointKind::PlungeRelease:
        command = Command::EinsaegenRelease;
        break;
    }
    if (correction && *correction == kKeepCorrection)
        return Error(
            Error::Kind::InvalidArgument,
            Tr::tr("a correction of -32768 would mean \"keep 2010h\"; leave it out instead"));
    const auto word = controlWord(command, speed);
    if (!word)
        return word.error();
    return send(node, { value, correction.value_or(kKeepCorrection), word.value() });
}

Result<void> Nm17xLine::jog(NodeId node, int direction, Speed speed)
{
    const auto word = controlWord(direction > 0 ? Command::JogRight : Command::JogLeft, speed);
    if (!word)
        return word.error();
    return send(node, { 0, kKeepCorrection, word.value() });
}

Result<void> Nm17xLine::stop(NodeId node)
{
    return send(node, { 0, kKeepCorrection, controlWord(Command::Stop).value() });
}

Result<void> Nm17xLine::broadcast(const Broadcast &command)
{
    if (!isBroadcastObject(command.index, command.subIndex))
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("%1 cannot be sent by broadcast; the displays would answer with EMCY "
                            "8220h")
                         .arg(ObjectAddress(command.index, command.subIndex).toString()));
    return sendFrame(kBroadcastCobId, encodeBroadcast(command));
}

Result<void> Nm17xLine::setUnit(bool inch)
{
    return broadcast({ 0, 0x2001, 0, inch ? 1u : 0u });
}

Result<void> Nm17xLine::showNodeIds(bool show)
{
    return broadcast({ 0, 0x2008, 0, show ? 1u : 0u });
}

Result<void> Nm17xLine::startGroup(int group)
{
    if (group < 1 || group > 8)
        return Error(Error::Kind::InvalidArgument, Tr::tr("group %1 is not 1..8").arg(group));
    return broadcast({ 0, 0x204D, 1, quint32(group) });
}

Result<void> Nm17xLine::stopAll()
{
    return broadcast({ 0, 0x204D, 1, 0 });
}

Result<void> Nm17xLine::presetAll(qint32 value)
{
    if (value < kMinPosition || value > kMaxPosition)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("preset %1 is outside -99999..999999 (1/100 mm)").arg(value));
    return broadcast({ 0, 0x6003, 0, quint32(value) });
}

const ObjectDef *Nm17xLine::definition(NodeId node, ObjectAddress address) const
{
    const ObjectDictionary *known = m_network->dictionary(node);
    if (known && !known->isEmpty())
        return known->find(address);
    static const ObjectDictionary every = dictionary(Variant::Nm174);
    return every.find(address);
}

Reply *Nm17xLine::write(NodeId node, ObjectAddress address, qint64 value)
{
    const ObjectDef *def = definition(node, address);
    if (!def || !def->writable())
        return Reply::failed(
            address,
            Error(Error::Kind::NotSupported,
                  Tr::tr("node %1 has no writable object %2").arg(node).arg(address.toString())));
    const auto raw = def->validate(QVariant(qlonglong(value)));
    if (!raw)
        return Reply::failed(address,
                             raw.error().prefixed(Tr::tr("node %1, %2").arg(node).arg(def->name)));
    const auto bytes = codec::encode(def->type, raw.value());
    if (!bytes)
        return Reply::failed(address, bytes.error());
    return m_network->sdo()->download(node, address, bytes.value());
}

Reply *Nm17xLine::read(NodeId node, ObjectAddress address)
{
    const ObjectDef *def = definition(node, address);
    if (!def)
        return Reply::failed(
            address,
            Error(Error::Kind::NotSupported,
                  Tr::tr("node %1 has no object %2").arg(node).arg(address.toString())));
    auto *outer = new Reply(address);
    Reply *inner = m_network->sdo()->upload(node, address);
    inner->setParent(outer); // a caller that drops `outer` drops the upload, too
    const DataType type = def->type;
    connect(inner, &Reply::finished, outer, [outer, inner, type, node, address] {
        inner->deleteLater();
        if (!inner->ok()) {
            outer->fail(
                inner->error().prefixed(Tr::tr("node %1, %2").arg(node).arg(address.toString())));
            return;
        }
        QByteArray bytes = inner->value().toByteArray();
        if (const int size = datatype::byteSize(type); size > 0 && bytes.size() > size)
            bytes.truncate(size); // an expedited answer without its size carries 4 bytes
        const auto raw = codec::decode(type, bytes);
        if (!raw) {
            outer->fail(raw.error());
            return;
        }
        outer->finish(QVariant(raw.value().toLongLong()));
    });
    return outer;
}

Reply *Nm17xLine::readState(NodeId node)
{
    auto *outer = new Reply(ObjectAddress(0x1018, 1));
    DisplayState state;
    state.node = node;
    readNext(outer, state, { { 0x1018, 1 }, { 0x1018, 2 }, { 0x1018, 4 } });
    return outer;
}

Reply *Nm17xLine::findDisplays()
{
    auto *outer = new Reply();
    auto *scanner = new NodeScanner(m_network->sdo(), m_network->monitor(), outer);
    m_problems.clear();
    connect(scanner, &NodeScanner::finished, outer, [this, outer, scanner] {
        QList<NodeId> displays;
        for (const NodeInfo &node : scanner->nodes()) {
            if (node.hasIdentity && variantOf(node.vendorId, node.productCode))
                displays.append(node.id);
        }
        readStates(outer, displays, {});
    });
    scanner->start();
    return outer;
}

void Nm17xLine::readStates(Reply *outer, QList<NodeId> todo, QList<DisplayState> done)
{
    if (todo.isEmpty()) {
        outer->finish(QVariant::fromValue(done));
        return;
    }
    Reply *inner = readState(todo.takeFirst());
    connect(inner, &Reply::finished, outer, [this, outer, inner, todo, done]() mutable {
        inner->deleteLater();
        if (inner->ok())
            done.append(inner->value().value<DisplayState>());
        else
            m_problems.append(inner->error().toString());
        readStates(outer, todo, done);
    });
}

// Reads `todo` one after the other; after the identity, the variant decides what follows.
void Nm17xLine::readNext(Reply *outer, DisplayState state, QList<ObjectAddress> todo)
{
    if (todo.isEmpty()) {
        outer->finish(QVariant::fromValue(state));
        return;
    }
    const ObjectAddress address = todo.takeFirst();
    Reply *inner = m_network->sdo()->upload(state.node, address);
    connect(inner, &Reply::finished, outer, [this, outer, inner, state, todo, address]() mutable {
        inner->deleteLater();
        if (!inner->ok()) {
            outer->fail(inner->error().prefixed(
                Tr::tr("node %1, %2").arg(state.node).arg(address.toString())));
            return;
        }
        const QByteArray bytes = inner->value().toByteArray();
        QByteArray padded = bytes;
        padded.resize(4, '\0');
        const quint32 v = qFromLittleEndian<quint32>(padded.constData());
        switch ((quint32(address.index) << 8) | address.sub) {
        case 0x101801:
        case 0x101802: {
            if (address.sub == 1) {
                state.serial = v; // vendor for now; checked with the product code
                break;
            }
            const auto variant = variantOf(state.serial, v);
            if (!variant) {
                outer->fail(Error(Error::Kind::NotSupported,
                                  Tr::tr("node %1 is no NM170/NM172/NM174 (vendor 0x%2, product "
                                         "0x%3)")
                                      .arg(state.node)
                                      .arg(state.serial, 8, 16, QLatin1Char('0'))
                                      .arg(v, 8, 16, QLatin1Char('0'))));
                return;
            }
            state.variant = *variant;
            // The network's readers (EMCY texts, the CAN monitor's PDO fields) learn the
            // display's objects; a description its own connection chose stays.
            if (!m_network->dictionary(state.node) || m_network->dictionary(state.node)->isEmpty())
                m_network->setDictionary(state.node, dictionary(*variant, state.node));
            todo.append({ { 0x6004, 0 }, { 0x2001, 0 } });
            if (hasMotor(*variant))
                todo.append({ { 0x204E, 1 }, { 0x204E, 2 } });
            else
                todo.append({ 0x1002, 0 });
            break;
        }
        case 0x101804:
            state.serial = v;
            break;
        case 0x600400:
            state.position = qint32(v);
            break;
        case 0x200100:
            state.inch = v == 1;
            break;
        case 0x204E01:
        case 0x100200:
            state.status = quint16(v);
            break;
        case 0x204E02:
            state.errors = quint16(v);
            break;
        default:
            break;
        }
        readNext(outer, state, todo);
    });
}

} // namespace db::nm17x
