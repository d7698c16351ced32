// ParameterRestore: the plan (which rows, in which safe order) and the report.

#include "parameterrunner_p.h"

#include <algorithm>

namespace db {

namespace restore {

bool isFatal(const Error &error)
{
    switch (error.kind()) {
    case Error::Kind::Disconnected:
    case Error::Kind::Cancelled:
    case Error::Kind::ConnectionRefused:
    case Error::Kind::HostNotFound:
    case Error::Kind::Io:
        return true;
    default:
        return false;
    }
}

quint16 pdoCommIndex(quint16 index)
{
    if ((index >= 0x1400 && index <= 0x15FF) || (index >= 0x1800 && index <= 0x19FF))
        return index;
    if (isMapping(index))
        return quint16(index - 0x200);
    return 0;
}

bool isMapping(quint16 index)
{
    return (index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF);
}

} // namespace restore

using restore::isMapping;
using restore::pdoCommIndex;

QString restoreOutcomeName(RestoreOutcome outcome)
{
    switch (outcome) {
    case RestoreOutcome::Verified:
        return QStringLiteral("verified");
    case RestoreOutcome::Written:
        return QStringLiteral("written");
    case RestoreOutcome::Failed:
        return QStringLiteral("failed");
    case RestoreOutcome::Mismatch:
        return QStringLiteral("mismatch");
    case RestoreOutcome::Skipped:
        return QStringLiteral("skipped");
    }
    return {};
}

ParameterRestore::ParameterRestore(DeviceConnection *connection, QObject *parent)
    : QObject(parent)
    , m_connection(connection)
    , m_steps(std::make_unique<std::vector<Step>>())
{ }

ParameterRestore::~ParameterRestore()
{
    delete m_inFlight.data();
}

void ParameterRestore::plan()
{
    m_steps->clear();
    m_report = RestoreReport();
    m_report.storeRequested = m_store;
    if (m_connection)
        m_report.addressFormat = &m_connection->addressFormat();
    m_current.clear();
    m_groupBlocked.clear();
    m_mappingBlocked.clear();
    m_disabled.clear();
    const ObjectDictionary *dict = m_connection ? &m_connection->dictionary() : nullptr;

    QList<ParameterEntry> chosen;
    for (const ParameterEntry &e : m_set.entries()) {
        if (m_selection.isEmpty() || m_selection.contains(e.address))
            chosen.append(e);
    }
    auto addRow = [&](const ParameterEntry &e, quint16 pdo, Step::Part part) {
        RestoreRow row;
        row.address = e.address;
        row.name = e.name;
        row.type = e.type;
        row.value = e.raw;
        const ObjectDef *def = dict ? dict->find(e.address) : nullptr;
        if (def) {
            row.name = def->name;
            row.type = def->type;
        }
        if (!def)
            row.reason = tr("not in the device description");
        else if (!def->writable())
            row.reason = tr("%1 object").arg(access::name(def->access));
        m_report.rows.append(row);
        if (row.reason.isEmpty()) // rows skipped by rule get no step
            m_steps->push_back(
                { Step::Kind::Row, e.address, int(m_report.rows.size() - 1), pdo, part });
    };
    auto writable = [&](const ParameterEntry &e) {
        const ObjectDef *def = dict ? dict->find(e.address) : nullptr;
        return def && def->writable();
    };

    // PDO groups first, each in the CiA 301 order (see the header).
    QList<quint16> pdos;
    for (const ParameterEntry &e : chosen) {
        const quint16 pdo = pdoCommIndex(e.address.index);
        if (pdo && writable(e) && !pdos.contains(pdo))
            pdos.append(pdo);
    }
    std::sort(pdos.begin(), pdos.end());
    for (const quint16 pdo : pdos) {
        const ObjectAddress cob { pdo, 1 };
        const ObjectAddress count { quint16(pdo + 0x200), 0 };
        const ParameterEntry *cobEntry = nullptr;
        const ParameterEntry *countEntry = nullptr;
        QList<ParameterEntry> comm;
        QList<ParameterEntry> entries;
        for (const ParameterEntry &e : chosen) {
            if (pdoCommIndex(e.address.index) != pdo || !writable(e))
                continue;
            if (e.address == cob)
                cobEntry = &e;
            else if (e.address == count)
                countEntry = &e;
            else if (isMapping(e.address.index))
                entries.append(e);
            else
                comm.append(e);
        }
        m_steps->push_back({ Step::Kind::ReadCurrent, cob, -1, pdo, Step::Part::Disable });
        m_steps->push_back({ Step::Kind::Disable, cob, -1, pdo, Step::Part::Disable });
        for (const ParameterEntry &e : comm)
            addRow(e, pdo, Step::Part::Comm);
        if (countEntry || !entries.isEmpty()) {
            if (!countEntry)
                m_steps->push_back(
                    { Step::Kind::ReadCurrent, count, -1, pdo, Step::Part::Mapping });
            m_steps->push_back({ Step::Kind::ClearMapping, count, -1, pdo, Step::Part::Mapping });
            for (const ParameterEntry &e : entries)
                addRow(e, pdo, Step::Part::Mapping);
            if (countEntry)
                addRow(*countEntry, pdo, Step::Part::Mapping);
            else
                m_steps->push_back({ Step::Kind::Previous, count, -1, pdo, Step::Part::Mapping });
        }
        if (cobEntry)
            addRow(*cobEntry, pdo, Step::Part::Enable);
        else
            m_steps->push_back({ Step::Kind::Previous, cob, -1, pdo, Step::Part::Enable });
    }
    for (const ParameterEntry &e : chosen) {
        if (!pdos.contains(pdoCommIndex(e.address.index)) || !writable(e))
            addRow(e, 0, Step::Part::None);
    }
}

} // namespace db
