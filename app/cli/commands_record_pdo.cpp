#include "commands_record_pdo.h"

#include "canopen/cannetwork.h"
#include "canopen/nodemonitor.h"
#include "canopen/pdoclient.h"
#include <QCoreApplication>

namespace {
// The context of this file's translated messages.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(cli)
};
} // namespace

namespace db::cli {

namespace {

// "TPDO1 (COB-ID 0x181)"
QString pdoName(const scope::PdoChannelPlanEntry &e)
{
    return Tr::tr("TPDO%1 (COB-ID 0x%2)")
        .arg(e.tpdoNumber + 1)
        .arg(e.mapping.cobId, 3, 16, QLatin1Char('0'));
}

} // namespace

Result<std::unique_ptr<scope::PdoSource>> makePdoSource(Context &c, DeviceConnection *connection,
                                                        const PdoRecordRequest &s,
                                                        scope::PdoChannelPlan &plan)
{
    const canopen::NetworkNode at = canopen::networkNodeOf(connection);
    if (!at)
        return Error(Error::Kind::InvalidArgument,
                     Tr::tr("--pdo and --configure-tpdo need a canopen+... URI"));
    const ObjectDictionary &dictionary = connection->dictionary();
    if (s.configureTpdo >= 0) {
        canopen::PdoClient client(at.network->sdo());
        const auto written = Reply::wait(scope::configureTpdo(&client, at.node, s.configureTpdo,
                                                              s.objects, dictionary, s.eventMs));
        // InvalidArgument is refused before any write; a device error may come half way.
        if (!written)
            return written.error().prefixed(
                Tr::tr("configuring TPDO%1 of node %2%3")
                    .arg(s.configureTpdo + 1)
                    .arg(at.node)
                    .arg(written.error().kind() == Error::Kind::InvalidArgument
                             ? QString()
                             : Tr::tr(" (it may be left disabled)")));
        c.err << Tr::tr("drivebench-cli: the PDO configuration of node %1 was changed (RAM "
                        "only, not stored): %2")
                     .arg(at.node)
                     .arg(written->value<canopen::PdoConfig>().toString())
              << Qt::endl;
    }
    const auto discovered = Reply::wait(scope::discoverPdoChannels(connection, s.objects));
    if (!discovered)
        return discovered.error();
    plan = discovered->value<scope::PdoChannelPlan>();
    if (!plan.isComplete())
        return Error(Error::Kind::InvalidArgument,
                     plan.missingText(dictionary)
                         + Tr::tr("; use --configure-tpdo N to map it (this changes the "
                                  "device's PDO configuration)"));
    auto source = std::make_unique<scope::PdoSource>(connection);
    if (auto added =
            scope::addPlannedChannels(*source, plan, dictionary, connection->uri().toString());
        !added)
        return added.error();
    for (const scope::PdoChannelPlanEntry &e : std::as_const(plan.found)) {
        const int size = datatype::byteSize(e.mapping.type);
        c.out << "pdo: " << connection->addressFormat().format(e.address) << " from " << pdoName(e)
              << " bytes " << e.mapping.byteOffset << ".." << e.mapping.byteOffset + size - 1;
        if (e.mapping.expectedPeriodMs > 0)
            c.out << ", every " << e.mapping.expectedPeriodMs << " ms";
        c.out << Qt::endl;
    }
    return source;
}

Error noPdoError(const Context &c, DeviceConnection *connection, const scope::PdoChannelPlan &plan,
                 int waitedMs)
{
    QStringList pdos;
    for (const scope::PdoChannelPlanEntry &e : plan.found) {
        if (!pdos.contains(pdoName(e)))
            pdos.append(pdoName(e));
    }
    const canopen::NetworkNode at = canopen::networkNodeOf(connection);
    const canopen::NmtState heard =
        at ? at.network->monitor()->state(plan.node) : canopen::NmtState::Unknown;
    QString text = Tr::tr("no PDO arrived from node %1 within %2 s (%3): %4")
                       .arg(plan.node)
                       .arg(waitedMs / 1000.0)
                       .arg(pdos.join(QStringLiteral(", ")), scope::silentPdoCause(plan, heard));
    if (heard != canopen::NmtState::Operational)
        text += Tr::tr(" (drivebench-cli nmt %1 start; record never changes the NMT "
                       "state)")
                    .arg(c.args.value(0));
    else
        text += Tr::tr(" (--configure-tpdo N --event-ms MS makes it cyclic)");
    return Error(Error::Kind::Timeout, text);
}

} // namespace db::cli
