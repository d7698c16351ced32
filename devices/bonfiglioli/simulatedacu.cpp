#include "simulatedacu.h"

#include "acudescription.h"

#include <QLoggingCategory>

#include <algorithm>

namespace db::bonfiglioli {

using namespace db::vabus;

namespace {

Q_LOGGING_CATEGORY(lcAcu, "drivebench.bonfiglioli.sim")

constexpr quint16 kLastError = 11;
constexpr quint16 kVersion = 12;
constexpr quint16 kBlockDefinition = 17;
constexpr quint16 kBlockWrite = 18;
constexpr quint16 kBlockRead = 19;
constexpr quint16 kCurrentFault = 260;
constexpr quint16 kWarnings = 270;
constexpr quint16 kApplicationWarnings = 274;
constexpr quint16 kBusErrorBehaviour = 388;
constexpr quint16 kControlWord = 410;
constexpr quint16 kStatusWord = 411;
constexpr quint16 kIpAddress = 1432;
constexpr quint16 kNetmask = 1433;
constexpr quint16 kIpCommand = 1437;
constexpr quint16 kCommunicationLoss = 0x2714; // F2714
constexpr quint8 kSysLocal = 0x00;
constexpr quint8 kSysLocalAscii = 0x30; // '0' of serial VABus, tolerated

constexpr quint16 kMode = 1454;

QByteArray word(quint16 v)
{
    QByteArray bytes;
    bytes.append(char(v & 0xFF));
    bytes.append(char(v >> 8));
    return bytes;
}

// 255.255.255.0 yes, 255.0.255.0 no.
bool contiguousMask(quint32 mask)
{
    const quint32 host = ~mask;
    return mask != 0 && (host & (host + 1)) == 0;
}

} // namespace

SimulatedAcu::SimulatedAcu(QObject *parent)
    : QObject(parent)
    , m_store(acuDictionary())
    , m_motion(m_store, m_indexed)
    , m_server(this)
{
    presetValues(m_store, 0);
    presetBlocks();
    for (const quint16 p : { kIpAddress, quint16(1433), quint16(1434), quint16(1435) }) {
        for (quint8 ds = 1; ds <= 4; ++ds)
            m_activeIp[p].append(m_store.value(p, ds));
    }
    m_watchdog.setSingleShot(true);
    m_watchdog.setInterval(kWatchdogMs);
    connect(&m_watchdog, &QTimer::timeout, this, &SimulatedAcu::onWatchdog);
    // Any telegram on the PLC port is an exchange; the first one arms the watchdog.
    connect(&m_server, &Server::exchanged, this, [this] { m_watchdog.start(); });
    connect(&m_server, &Server::logLine, this, &SimulatedAcu::logLine);
}

SimulatedAcu::~SimulatedAcu() = default;

// The values the VABus examples read and write, and the limits they show.
void SimulatedAcu::presetValues(AcuStore &store, quint8 nodeId)
{
    const auto u = [](qulonglong v) {
        return QVariant::fromValue(v);
    };
    const auto i = [](qlonglong v) {
        return QVariant::fromValue(v);
    };
    store.set(kVersion, 0, QStringLiteral("5.3.2 STO"));
    store.set(29, 0,
              nodeId ? QStringLiteral("ACU node %1").arg(nodeId) : QStringLiteral("ACU simulated"));
    store.set(372, 0, u(1390));
    store.set(376, 0, u(55)); // 5.5 kW
    store.set(481, 1, i(1000));
    store.set(481, 2, i(1500));
    store.set(481, 3, i(2000));
    store.set(481, 4, i(2500));
    store.set(482, 0, i(4345));
    store.set(210, 0, i(10845));
    store.set(211, 0, i(102));
    store.set(213, 0, i(40));
    store.set(1431, 0,
              QStringLiteral("MAC-ID 00:1B:2C:00:00:%1 Sno 4711 HW 1.0 SW 1.2")
                  .arg(nodeId, 2, 16, QLatin1Char('0')));
    // 376 refuses 0 kW; fixed frequencies end at 999.99 Hz.
    store.set(1441, 0, QStringLiteral("Please call the service, ext. 2121"));
    store.setLimits(376, u(1), u(65535));
    for (const quint16 p : { quint16(480), quint16(481), quint16(482) })
        store.setLimits(p, i(-99999), i(99999));
    for (const quint16 p : { quint16(30), quint16(372), quint16(373), quint16(376) })
        store.setLockedWhileRunning(p);
    for (const quint16 p : { kBlockDefinition, kBlockWrite, kBlockRead })
        store.setMaxLength(p, 64);
    store.setMaxLength(1441, 40);
    // A positioning configuration under state machine control, with a drive train of 10000 u
    // per revolution and ramps that end a test move within seconds.
    store.set(30, 0, u(240));
    store.set(412, 0, u(1));
    store.set(373, 0, u(2));
    store.set(1115, 0, i(10000));
    store.set(1116, 0, u(1));
    store.set(1117, 0, u(1));
    for (const quint16 p : { quint16(420), quint16(421), quint16(422), quint16(423) })
        store.set(p, 0, i(5000)); // 50.00 Hz/s
    store.set(1132, 0, i(20000));
    store.set(1133, 0, i(2000));
    store.set(1134, 0, i(50000));
    store.set(1179, 0, i(200000));
    store.set(1276, 0, u(10));
    // The override profile of a commissioned axis (the factory setting -1 would leave it to
    // the MCI links).
    store.set(1456, 0, i(10000));
    store.set(1457, 0, i(50000));
    store.set(1458, 0, i(50000));
}

// Motion blocks 2-4 (1 stays empty): 2 absolute 5000 u, 3 relative 2000 u, 4 absolute 123000 u
// and on to block 2 in a sequence.
void SimulatedAcu::presetBlocks()
{
    struct Block
    {
        int index;
        qlonglong target, speed, acc, dec, mode, next;
    };
    for (const Block &b : { Block { 2, 5000, 20000, 50000, 50000, 1, 0 },
                            Block { 3, 2000, 10000, 50000, 50000, 2, 0 },
                            Block { 4, 123000, 40000, 50000, 50000, 1, 2 } }) {
        m_indexed.preset(1202, b.index, b.target);
        m_indexed.preset(1203, b.index, b.speed);
        m_indexed.preset(1204, b.index, b.acc);
        m_indexed.preset(1206, b.index, b.dec);
        m_indexed.preset(1208, b.index, b.mode);
        m_indexed.preset(1213, b.index, b.next);
    }
}

Result<void> SimulatedAcu::listen(quint16 port)
{
    return m_server.listen(port);
}

quint16 SimulatedAcu::port() const
{
    return m_server.port();
}

void SimulatedAcu::setWatchdogMs(int ms)
{
    m_watchdog.setInterval(qMax(1, ms));
}

void SimulatedAcu::setStartupDelayMs(int ms)
{
    m_starting.setSingleShot(true);
    if (ms > 0)
        m_starting.start(ms);
    else
        m_starting.stop();
}

void SimulatedAcu::addSystemBusSlave(quint8 nodeId)
{
    auto store = std::make_shared<AcuStore>(acuDictionary());
    presetValues(*store, nodeId);
    m_slaves.insert(nodeId, store);
}

void SimulatedAcu::powerCycle()
{
    m_store.powerCycle();
    m_indexed.powerCycle();
    for (const auto &slave : std::as_const(m_slaves))
        slave->powerCycle();
    m_block.clear();
    m_watchdog.stop();
    m_motion.powerCycle();
}

void SimulatedAcu::restart(int offMs)
{
    const quint16 port = m_server.port();
    m_server.close();
    powerCycle();
    Q_EMIT logLine(QStringLiteral("power off for %1 ms").arg(offMs));
    QTimer::singleShot(qMax(0, offMs), this, [this, port] {
        if (auto listening = m_server.listen(port); !listening)
            Q_EMIT logLine(
                QStringLiteral("cannot listen again: %1").arg(listening.error().toString()));
        else
            Q_EMIT logLine(QStringLiteral("power on, listening on port %1").arg(port));
    });
}

int SimulatedAcu::dropClient()
{
    const bool had = m_server.hasClient();
    const quint16 port = m_server.port();
    m_server.close();
    if (auto listening = m_server.listen(port); !listening)
        Q_EMIT logLine(QStringLiteral("cannot listen again: %1").arg(listening.error().toString()));
    return had ? 1 : 0;
}

quint16 SimulatedAcu::statusWord() const
{
    quint16 status = m_motion.statusWord();
    if (m_warnings || m_appWarnings)
        status |= 0x0080;
    if (m_warning2)
        status |= 0x8000;
    return status;
}

void SimulatedAcu::raiseFault(quint16 code)
{
    m_motion.raiseFault(code);
}

void SimulatedAcu::setWarnings(quint16 bits)
{
    m_warnings = bits & 0x7FFF;
}

void SimulatedAcu::setApplicationWarnings(quint16 bits)
{
    m_appWarnings = bits;
}

void SimulatedAcu::setWarning2(bool on)
{
    m_warning2 = on;
}

void SimulatedAcu::onWatchdog()
{
    const int reaction = m_store.value(kBusErrorBehaviour, 0).toInt();
    const QString line =
        QStringLiteral("no exchange on the PLC port for %1 ms: reaction %2 of parameter 388")
            .arg(m_watchdog.interval())
            .arg(reaction);
    qCInfo(lcAcu).noquote() << line;
    Q_EMIT logLine(line);
    switch (reaction) {
    case 0: // no reaction: the operating point is kept
        break;
    case 2: // switch off
    case 3: // quick stop; both end in "switch on disabled"
        m_motion.switchOff(reaction == 3);
        break;
    default: // 1 fault at once; 4, 5 stop first, then fault
        raiseFault(kCommunicationLoss);
        break;
    }
    Q_EMIT communicationLost(reaction);
}

std::optional<Telegram> SimulatedAcu::handle(const Telegram &request)
{
    if (m_starting.isActive())
        return std::nullopt; // still initialising
    AcuStore::Outcome outcome;
    if (request.sys == kSysLocal || request.sys == kSysLocalAscii) {
        bool handled = false;
        outcome = special(request, &handled);
        if (!handled && m_indexed.handles(request.parameter))
            outcome = m_indexed.access(request, m_store);
        else if (!handled)
            outcome = access(m_store, request);
    } else if (request.sys > kSlaveSysBase && m_slaves.contains(request.sys - kSlaveSysBase)) {
        outcome = access(*m_slaves.value(request.sys - kSlaveSysBase), request);
    } else {
        outcome.error = NodeNotAvailable;
    }
    if (outcome.error) {
        m_lastError = outcome.error;
        return Telegram::errorAnswer(request, outcome.error);
    }
    Telegram answer = request;
    answer.data = outcome.data;
    return answer;
}

AcuStore::Outcome SimulatedAcu::access(AcuStore &store, const Telegram &request)
{
    return request.write
        ? store.write(request.parameter, request.dataSet, request.data, isRunning())
        : store.read(request.parameter, request.dataSet);
}

// Parameters the inverter computes or acts on rather than stores.
AcuStore::Outcome SimulatedAcu::special(const Telegram &request, bool *handled)
{
    *handled = true;
    const bool single = request.dataSet == 0 || request.dataSet == kRamDataSetOffset;
    switch (request.parameter) {
    case kStatusWord:
    case kCurrentFault:
    case kWarnings:
    case kApplicationWarnings:
    case kLastError: {
        if (request.write)
            return { NotWritable, {} };
        if (request.dataSet != 0)
            return { InvalidDataSet, {} };
        const quint16 v = request.parameter == kStatusWord ? statusWord()
            : request.parameter == kCurrentFault           ? fault()
            : request.parameter == kWarnings ? quint16(m_warnings | (m_appWarnings ? 0x8000 : 0))
            : request.parameter == kApplicationWarnings ? m_appWarnings
                                                        : m_lastError;
        return { NoError, word(v) };
    }
    case kControlWord:
        if (!request.write || !single) {
            *handled = false;
            return {};
        }
        return writeControlWord(request);
    case kMode:
        return writeMode(request, handled);
    case kBlockDefinition:
        if (!request.write || request.dataSet != 0) {
            *handled = false;
            return {};
        }
        return writeBlockDefinition(request.data);
    case kBlockRead:
        if (request.write || request.dataSet != 0) {
            *handled = false;
            return {};
        }
        return readBlock();
    case kBlockWrite:
        if (!request.write || request.dataSet != 0) {
            *handled = false;
            return {};
        }
        return writeBlock(request.data);
    case kIpCommand:
        if (!request.write) {
            *handled = false;
            return {};
        }
        return ipCommand(request.data);
    default:
        *handled = false;
        return {};
    }
}

// The state machine and the axis act on the control word (AcuMotion). Data set 0 is the EEPROM
// one and counts as an EEPROM write, 5 its RAM copy.
AcuStore::Outcome SimulatedAcu::writeControlWord(const Telegram &request)
{
    if (request.data.size() != 2)
        return { LengthMismatch, {} };
    const quint16 cw = quint16(quint8(request.data.at(0)) | (quint8(request.data.at(1)) << 8));
    const auto stored = m_store.write(kControlWord, request.dataSet, request.data);
    if (stored.error)
        return stored;
    if (request.dataSet == 0)
        ++m_controlWritesEeprom;
    else
        ++m_controlWritesRam;
    if (const quint16 error = m_motion.writeControlWord(cw))
        return { error, {} };
    return { NoError, request.data };
}

// 1454 takes only the modes the override has; without positioning control it stays 2.
AcuStore::Outcome SimulatedAcu::writeMode(const Telegram &request, bool *handled)
{
    if (!request.write || request.data.size() != 2) {
        *handled = false;
        return {};
    }
    const qint64 mode = quint16(quint8(request.data.at(0)) | (quint8(request.data.at(1)) << 8));
    const qint64 signedMode = qint16(mode) < 0 ? 256 + qint16(mode) : mode; // -1 -> 255
    if (const quint16 error = m_motion.checkMode(signedMode))
        return { error, {} };
    const QByteArray data = word(quint16(signedMode));
    const auto stored = m_store.write(kMode, request.dataSet, data, false);
    if (stored.error)
        return stored;
    return { NoError, request.data };
}

// "Sdnnn" groups: system bus node '0', data set digit, three-digit parameter number (8.2).
AcuStore::Outcome SimulatedAcu::writeBlockDefinition(const QByteArray &data)
{
    if (data.isEmpty() || data.size() % 5 != 0 || data.size() > 64)
        return { InvalidValue, {} };
    QList<BlockItem> items;
    for (qsizetype i = 0; i < data.size(); i += 5) {
        const QByteArray group = data.mid(i, 5);
        bool ok = false;
        const uint parameter = group.mid(2).toUInt(&ok);
        const int dataSet = group.at(1) - '0';
        if (group.at(0) != '0' || dataSet < 0 || dataSet > 4 || !ok)
            return { InvalidValue, {} };
        const DataType type = m_store.type(quint16(parameter));
        if (!m_store.knows(quint16(parameter)))
            return { UnknownParameter, {} };
        if (type == DataType::VisibleString)
            return { InvalidValue, {} };
        items.append({ quint16(parameter), quint8(dataSet) });
    }
    m_block = items;
    return { NoError, data };
}

AcuStore::Outcome SimulatedAcu::readBlock()
{
    if (m_block.isEmpty())
        return { InvalidValue, {} };
    QByteArray text;
    for (const BlockItem &item : std::as_const(m_block)) {
        const Telegram request = Telegram::readRequest(item.parameter, item.dataSet);
        bool handled = false;
        AcuStore::Outcome one = special(request, &handled);
        if (!handled)
            one = m_store.read(item.parameter, item.dataSet);
        if (one.error)
            return one;
        QByteArray bigEndian = one.data;
        std::reverse(bigEndian.begin(), bigEndian.end());
        text += bigEndian.toHex().toUpper();
    }
    return { NoError, text };
}

AcuStore::Outcome SimulatedAcu::writeBlock(const QByteArray &data)
{
    if (m_block.isEmpty())
        return { InvalidValue, {} };
    qsizetype pos = 0;
    QList<std::pair<BlockItem, QByteArray>> values;
    for (const BlockItem &item : std::as_const(m_block)) {
        const int digits = datatype::byteSize(m_store.type(item.parameter)) * 2;
        const QByteArray hexText = data.mid(pos, digits);
        pos += digits;
        QByteArray bytes = QByteArray::fromHex(hexText);
        if (hexText.size() != digits || bytes.size() * 2 != digits)
            return { InvalidValue, {} };
        std::reverse(bytes.begin(), bytes.end());
        values.append({ item, bytes });
    }
    if (pos != data.size())
        return { InvalidValue, {} };
    for (const auto &[item, bytes] : values) {
        const auto one = m_store.write(item.parameter, item.dataSet, bytes, isRunning());
        if (one.error)
            return one;
    }
    return { NoError, data };
}

// 1437: 0 applies the buffered 1432-1435 if they are valid, else the buffer returns to the
// active values; 1 reloads the active values into the buffer.
AcuStore::Outcome SimulatedAcu::ipCommand(const QByteArray &data)
{
    if (data.size() != 2)
        return { LengthMismatch, {} };
    const quint16 command = quint16(quint8(data.at(0)) | (quint8(data.at(1)) << 8));
    if (command > 1)
        return { InvalidValue, {} };
    const auto address = [this](quint16 p) {
        quint32 v = 0;
        for (quint8 ds = 1; ds <= 4; ++ds)
            v = (v << 8) | (m_store.value(p, ds).toUInt() & 0xFF);
        return v;
    };
    const quint32 ip = address(kIpAddress);
    const bool valid =
        command == 0 && ip != 0 && ip != 0xFFFFFFFF && contiguousMask(address(kNetmask));
    if (valid) {
        for (auto it = m_activeIp.begin(); it != m_activeIp.end(); ++it) {
            for (quint8 ds = 1; ds <= 4; ++ds)
                it.value()[ds - 1] = m_store.value(it.key(), ds);
        }
    } else {
        for (auto it = m_activeIp.cbegin(); it != m_activeIp.cend(); ++it) {
            for (quint8 ds = 1; ds <= 4; ++ds)
                m_store.set(it.key(), ds, it.value().at(ds - 1));
        }
    }
    return { NoError, data };
}

} // namespace db::bonfiglioli
