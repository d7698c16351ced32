#include "vabusclient.h"

#include "vabuslogging.h"

#include <QCoreApplication>
#include <QMetaMethod>

namespace db::vabus {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::vabus)
};

Error invalid(const QString &message)
{
    return Error(Error::Kind::InvalidArgument, message);
}

} // namespace

QString label(const Telegram &t)
{
    QString text = QStringLiteral("%1:%2").arg(t.parameter).arg(t.dataSet);
    if (t.sys != 0)
        text += QStringLiteral(" (SYS 0x%1)").arg(t.sys, 2, 16, QLatin1Char('0'));
    return text;
}

VabusClient::VabusClient(ByteStream *stream, QObject *parent)
    : QObject(parent)
    , m_engine(stream, &lcVabus, &lcVabusRaw, this)
{
    m_engine.setTimeoutMs(kDefaultTimeoutMs);
    m_engine.setMaxTransmissions(kMaxTransmissions);
    m_engine.setDropsPartialAnswerOnTimeout(true);
    m_engine.setLateGraceMs(kLateGraceMs);
    updateKeepAlive();
}

VabusClient::~VabusClient()
{
    m_engine.failAll(Error(Error::Kind::Cancelled, QStringLiteral("VABus client deleted")));
}

void VabusClient::setSys(quint8 sys)
{
    m_sys = sys;
    updateKeepAlive();
}

void VabusClient::setKeepAliveIdleMs(int ms)
{
    m_keepAliveIdleMs = qMax(0, ms);
    updateKeepAlive();
}

void VabusClient::updateKeepAlive()
{
    const Telegram request = Telegram::readRequest(kKeepAliveParameter, 0, m_sys);
    m_engine.setKeepAlive(m_keepAliveIdleMs, encode(request).value(),
                          QStringLiteral("keep-alive read %1").arg(label(request)),
                          Protocol::Matcher { request, DataType::Unsigned16 });
}

Reply *VabusClient::read(quint16 parameter, quint8 dataSet, std::optional<DataType> type,
                         ObjectAddress address)
{
    auto *reply = new Reply(address);
    read(parameter, dataSet, type, Completion(reply));
    return reply;
}

void VabusClient::read(quint16 parameter, quint8 dataSet, std::optional<DataType> type,
                       Completion done)
{
    if (dataSet > kMaxReadDataSet) {
        done.completeLater(invalid(QStringLiteral("VABus reads data sets 0-4, not %1 (5-9 are "
                                                  "the RAM copies, written only)")
                                       .arg(dataSet)));
        return;
    }
    if (type && !isCarried(*type)) {
        done.completeLater(encodeValue(*type, {}).error());
        return;
    }
    submit(Telegram::readRequest(parameter, dataSet, m_sys), type, std::move(done));
}

Reply *VabusClient::write(quint16 parameter, quint8 dataSet, DataType type, const QVariant &raw,
                          ObjectAddress address)
{
    auto data = encodeValue(type, raw);
    if (!data)
        return Reply::failed(
            address, data.error().prefixed(QStringLiteral("%1:%2").arg(parameter).arg(dataSet)));
    return writeData(parameter, dataSet, data.value(), address);
}

Reply *VabusClient::writeData(quint16 parameter, quint8 dataSet, const QByteArray &data,
                              ObjectAddress address)
{
    if (dataSet > kMaxWriteDataSet)
        return Reply::failed(address,
                             invalid(Tr::tr("VABus writes data sets 0-9, not %1").arg(dataSet)));
    return submit(Telegram::writeRequest(parameter, dataSet, data, m_sys), std::nullopt, address);
}

Reply *VabusClient::submit(const Telegram &request, std::optional<DataType> type,
                           ObjectAddress address)
{
    auto *reply = new Reply(address);
    submit(request, type, Completion(reply));
    return reply;
}

void VabusClient::submit(const Telegram &request, std::optional<DataType> type, Completion done)
{
    auto bytes = encode(request);
    if (!bytes) {
        done.completeLater(bytes.error());
        return;
    }
    const QString what = (request.write ? QStringLiteral("write ") : QStringLiteral("read "))
        + label(request) + (request.write ? QStringLiteral(" = ") + hex(request.data) : QString());
    m_engine.submit(bytes.value(), what, Protocol::Matcher { request, type }, std::move(done));
}

Verdict VabusClient::Protocol::Matcher::operator()(const Answer &answer) const
{
    const QString what = label(request);
    if (answer.kind != Frame::Kind::Telegram)
        return Verdict::retry(Error(Error::Kind::Malformed,
                                    QStringLiteral("%1 answered %2: %3")
                                        .arg(what, answer.problem, hex(answer.bytes.left(16)))));
    const Telegram &t = answer.telegram;
    if (t.write != request.write || t.sys != request.sys || t.dataSet != request.dataSet
        || t.parameter != request.parameter)
        return Verdict::notMine(
            QStringLiteral("answer is for %1 %2")
                .arg(t.write ? QStringLiteral("write") : QStringLiteral("read"), label(t)));
    if (t.error) {
        const quint16 code = t.errorCode();
        return Verdict::mine(
            Error(Error::Kind::DeviceError,
                  (request.write ? Tr::tr("inverter refused write of %1: VABus error %2, %3")
                                 : Tr::tr("inverter refused read of %1: VABus error %2, %3"))
                      .arg(what)
                      .arg(code)
                      .arg(errorText(code)),
                  code));
    }
    if (request.write) {
        if (t.data != request.data)
            return Verdict::retry(Error(Error::Kind::Malformed,
                                        QStringLiteral("write echo of %1 is %2, sent %3")
                                            .arg(what, hex(t.data), hex(request.data))));
        return Verdict::mine(QVariant());
    }
    const DataType decodeAs = type.value_or(typeForSize(t.data.size()));
    if (t.data.isEmpty() && decodeAs != DataType::VisibleString) // an empty string has no data
        return Verdict::retry(Error(Error::Kind::Malformed,
                                    QStringLiteral("answer to %1 carries no value").arg(what)));
    auto value = decodeValue(decodeAs, t.data);
    if (!value)
        return Verdict::retry(value.error().prefixed(what));
    return Verdict::mine(value.value());
}

QString VabusClient::Protocol::summary(const Answer &answer)
{
    if (answer.kind != Frame::Kind::Telegram)
        return answer.problem;
    const Telegram &t = answer.telegram;
    if (t.error)
        return QStringLiteral("error %1 (%2)").arg(t.errorCode()).arg(errorText(t.errorCode()));
    return t.data.isEmpty() ? QStringLiteral("(no data)") : hex(t.data);
}

QString VabusClient::Protocol::identify(const Answer &answer)
{
    if (answer.kind != Frame::Kind::Telegram)
        return answer.problem;
    return label(answer.telegram);
}

void VabusClient::connectNotify(const QMetaMethod &signal)
{
    if (!m_forwardingLog && signal == QMetaMethod::fromSignal(&VabusClient::logLine)) {
        m_forwardingLog = true;
        connect(&m_engine, &RequestEngineBase::logLine, this, &VabusClient::logLine);
    }
}

} // namespace db::vabus
