#include "movingcaprefgohandler.h"

#include "movingcapdrive.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::refgo)
};
} // namespace

namespace db::refgo {

namespace {
QStringList errorLine(const Error &error)
{
    return { QStringLiteral("ERROR ") + error.message() };
}

QStringList done(const Result<void> &result)
{
    return result ? QStringList() : errorLine(result.error());
}

// The request text without its hex-output flag: "OR6041,0,h" and "OR6041,0h" -> "OR6041,0".
QString withoutHexFlag(const Request &request)
{
    QString text = request.text.trimmed();
    if (!request.hexOutput)
        return text;
    if (text.endsWith(QLatin1String(",h"), Qt::CaseInsensitive))
        return text.chopped(2);
    if (text.endsWith(QLatin1Char('h'), Qt::CaseInsensitive))
        return text.chopped(1);
    return text;
}

// Spec 3.2: hex output has no leading zeros and a trailing 'h'; negative values are shown as
// the two's complement bit pattern of the object's width.
QString formatValue(const QVariant &raw, DataType type, bool hex)
{
    if (raw.typeId() == QMetaType::Bool)
        return raw.toBool() ? QStringLiteral("1") : QStringLiteral("0");
    if (!datatype::isInteger(type))
        return raw.toString();
    if (!hex)
        return datatype::isSignedInteger(type) ? QString::number(raw.toLongLong())
                                               : QString::number(raw.toULongLong());
    const int bits = datatype::byteSize(type) * 8;
    quint64 pattern = quint64(raw.toLongLong());
    if (bits < 64)
        pattern &= (quint64(1) << bits) - 1;
    return QString::number(pattern, 16).toUpper() + QLatin1Char('h');
}
} // namespace

MovingCapRefgoHandler::MovingCapRefgoHandler(sim::MovingCapDrive *drive)
    : m_drive(drive)
{ }

QStringList MovingCapRefgoHandler::readObject(const Request &request)
{
    auto value = m_drive->read(request.address);
    if (!value)
        return errorLine(value.error());
    const ObjectDef *def = m_drive->dictionary().find(request.address);
    const DataType type = def ? def->type : DataType::Unsigned32;
    // 1003h: the manual prints the history in hex even without ",h" (spec 6.5, errata 14).
    const bool hex = request.hexOutput || request.address.index == 0x1003;
    return { withoutHexFlag(request) + QLatin1Char(',') + formatValue(value.value(), type, hex) };
}

QStringList MovingCapRefgoHandler::writeObject(const Request &request)
{
    if (auto ok = m_drive->write(request.address, request.value); !ok)
        return errorLine(ok.error());
    return { request.text.trimmed() + QLatin1String(",OK") };
}

QStringList MovingCapRefgoHandler::handle(const Request &r)
{
    const auto arg = r.argument;
    switch (r.command) {
    case Command::G:
        return done(m_drive->go(arg));
    case Command::GW:
        return done(m_drive->goWay(arg));
    case Command::PO:
        return done(m_drive->setTargetPosition(arg.value_or(0)));
    case Command::WA:
        return done(m_drive->setWay(arg.value_or(0)));
    case Command::SM:
        return done(m_drive->stopMotion());
    case Command::PWC:
        return done(m_drive->powerContinue());
    case Command::CM:
        return done(m_drive->continueMotion());
    case Command::REF:
        return done(m_drive->reference(arg ? std::optional<int>(int(*arg)) : std::nullopt));
    case Command::PQ:
        return done(m_drive->powerQuit());
    case Command::OW:
        return writeObject(r);
    case Command::OR:
        return readObject(r);
    case Command::TPSR:
        return { formatTpsr(m_drive->tpsr()) };
    case Command::TS:
        return { QString::number(m_drive->ts()) };
    case Command::TP: {
        auto position = m_drive->read({ 0x6064, 0 });
        return position ? QStringList { QString::number(position->toLongLong()) }
                        : errorLine(position.error());
    }
    case Command::SP:
        return done(m_drive->setSpeed(arg.value_or(0)));
    case Command::AC:
        return done(m_drive->write({ 0x6083, 0 }, QVariant::fromValue<qlonglong>(arg.value_or(0))));
    case Command::DE:
        return done(m_drive->write({ 0x6084, 0 }, QVariant::fromValue<qlonglong>(arg.value_or(0))));
    case Command::ACV:
        return done(m_drive->write({ 0x60A4, 0 }, QVariant::fromValue<qlonglong>(arg.value_or(0))));
    case Command::JP:
    case Command::JN: {
        std::optional<int> ms;
        if (arg)
            ms = int(*arg);
        return done(m_drive->jog(r.command == Command::JP ? 1 : -1, ms));
    }
    case Command::RR:
        return done(m_drive->repeatReverse(arg));
    case Command::RW:
        m_drive->setRepeatWay(arg.value_or(0));
        return {};
    case Command::WT:
        m_drive->setRepeatWait(arg.value_or(0));
        return {};
    case Command::SO:
    case Command::CO:
        return done(m_drive->setOutput(int(arg.value_or(0)), r.command == Command::SO));
    case Command::TI: {
        auto level = m_drive->input(int(arg.value_or(0)));
        return level ? QStringList { *level ? QStringLiteral("1") : QStringLiteral("0") }
                     : errorLine(level.error());
    }
    }
    return errorLine(Error(Error::Kind::NotSupported, Tr::tr("command not supported")));
}

} // namespace db::refgo
