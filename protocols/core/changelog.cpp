#include "changelog.h"
#include "filewriter.h"

#include "deviceconnection.h"
#include "reply.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>

namespace db {

namespace {

QString csvField(const QString &text)
{
    // Quoted always: values may hold the separator, quotes or line breaks from a device.
    QString quoted = text;
    quoted.replace(QLatin1Char('"'), QStringLiteral("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

} // namespace

ChangeLog::ChangeLog(QObject *parent)
    : QObject(parent)
{ }

const ChangeLog::Entry *ChangeLog::find(int id) const
{
    const int i = indexOf(id);
    return i < 0 ? nullptr : &m_entries.at(i);
}

int ChangeLog::indexOf(int id) const
{
    // Ids grow with the index; entries are only ever dropped at the front.
    if (m_entries.isEmpty())
        return -1;
    const int i = id - m_entries.first().id;
    if (i < 0 || i >= m_entries.size() || m_entries.at(i).id != id)
        return -1;
    return i;
}

int ChangeLog::add(Entry entry)
{
    if (m_entries.size() >= kMaxEntries) {
        const int drop = int(m_entries.size()) - kMaxEntries + 1;
        m_entries.remove(0, drop);
        Q_EMIT entriesRemoved(0, drop);
    }
    entry.id = m_nextId++;
    if (!entry.time.isValid())
        entry.time = QDateTime::currentDateTime();
    m_entries.append(entry);
    Q_EMIT entryAdded(int(m_entries.size()) - 1);
    return entry.id;
}

void ChangeLog::complete(int id, const Error &error)
{
    complete(id, error.isError() ? Outcome::Failed : Outcome::Ok,
             error.isError() ? error.toString() : QString());
}

void ChangeLog::complete(int id, Outcome outcome, const QString &message)
{
    const int i = indexOf(id);
    if (i < 0 || m_entries.at(i).outcome != Outcome::Pending || outcome == Outcome::Pending)
        return;
    Entry &e = m_entries[i];
    e.outcome = outcome;
    e.message = message;
    Q_EMIT entryChanged(i);
}

int ChangeLog::track(Entry entry, Reply *reply)
{
    const int id = add(entry);
    if (!reply) {
        complete(id, Error(Error::Kind::Cancelled, tr("not sent")));
        return id;
    }
    if (reply->isFinished()) {
        complete(id, reply->error());
        return id;
    }
    connect(reply, &Reply::finished, this, [this, id, reply] { complete(id, reply->error()); });
    // A reply deleted unfinished (its owner went away) leaves no pending entry behind.
    connect(reply, &QObject::destroyed, this,
            [this, id] { complete(id, Error(Error::Kind::Cancelled, tr("no answer"))); });
    return id;
}

void ChangeLog::markStored(const QString &device)
{
    for (int i = 0; i < m_entries.size(); ++i) {
        Entry &e = m_entries[i];
        if (e.device == device && e.storable && !e.stored && e.outcome == Outcome::Ok) {
            e.stored = true;
            Q_EMIT entryChanged(i);
        }
    }
}

int ChangeLog::unstoredCount(const QString &device) const
{
    int n = 0;
    for (const Entry &e : m_entries)
        n += (e.device == device && e.storable && !e.stored && e.outcome == Outcome::Ok) ? 1 : 0;
    return n;
}

void ChangeLog::clear()
{
    const int n = int(m_entries.size());
    m_entries.clear();
    if (n > 0)
        Q_EMIT entriesRemoved(0, n);
    Q_EMIT cleared();
}

ChangeLog::Entry ChangeLog::writeEntry(const DeviceConnection &connection, ObjectAddress address,
                                       const QString &oldValue, const QString &newValue,
                                       bool workingMemoryOnly)
{
    Entry e;
    e.device = connection.uri().toString();
    e.kind = Kind::Write;
    e.object = connection.addressFormat().format(address);
    if (const ObjectDef *def = connection.dictionary().find(address); def && !def->name.isEmpty())
        e.object += QLatin1Char(' ') + def->name;
    e.oldValue = oldValue;
    e.newValue = newValue;
    e.workingMemoryOnly = workingMemoryOnly;
    e.storable = !workingMemoryOnly
        && connection.capabilities().testFlag(DeviceConnection::Capability::StoreNonVolatile);
    return e;
}

QString ChangeLog::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Write:
        return tr("write");
    case Kind::Restore:
        return tr("restore");
    case Kind::Store:
        return tr("store permanently");
    case Kind::Enable:
        return tr("enable");
    case Kind::Disable:
        return tr("disable");
    case Kind::Motion:
        return tr("motion");
    case Kind::Nmt:
        return tr("NMT");
    case Kind::Reset:
        return tr("fault reset");
    case Kind::Frame:
        return tr("CAN frame");
    }
    return {};
}

QString ChangeLog::outcomeName(Outcome outcome)
{
    switch (outcome) {
    case Outcome::Pending:
        return tr("pending");
    case Outcome::Ok:
        return tr("ok");
    case Outcome::Failed:
        return tr("failed");
    case Outcome::Aborted:
        return tr("aborted");
    }
    return {};
}

QString ChangeLog::storedText(const Entry &entry)
{
    if (entry.workingMemoryOnly)
        return tr("RAM only");
    if (!entry.storable || entry.outcome != Outcome::Ok)
        return {};
    return entry.stored ? tr("yes") : tr("no");
}

QString ChangeLog::summary(const Entry &entry)
{
    QString text = entry.device + QStringLiteral(": ") + kindName(entry.kind);
    if (!entry.object.isEmpty())
        text += QLatin1Char(' ') + entry.object;
    if (!entry.oldValue.isEmpty() && !entry.newValue.isEmpty())
        text += QStringLiteral(" %1 \u2192 %2").arg(entry.oldValue, entry.newValue);
    else if (!entry.newValue.isEmpty())
        text += QStringLiteral(" = ") + entry.newValue;
    text += QStringLiteral(": ") + outcomeName(entry.outcome);
    if (!entry.message.isEmpty())
        text += QStringLiteral(" (") + entry.message + QLatin1Char(')');
    if (entry.workingMemoryOnly && entry.outcome == Outcome::Ok)
        text += QStringLiteral(", ") + tr("RAM only, lost at power-off");
    return text;
}

QString ChangeLog::toCsv() const
{
    QString out =
        QStringLiteral("time,device,action,object,old value,new value,result,message,stored\n");
    for (const Entry &e : m_entries) {
        const QString stored = storedText(e);
        const QStringList fields {
            e.time.toString(Qt::ISODateWithMs),
            e.device,
            kindName(e.kind),
            e.object,
            e.oldValue,
            e.newValue,
            outcomeName(e.outcome),
            e.message,
            stored,
        };
        QStringList quoted;
        for (const QString &f : fields)
            quoted << csvField(f);
        out += quoted.join(QLatin1Char(',')) + QLatin1Char('\n');
    }
    return out;
}

Error ChangeLog::saveCsv(const QString &path) const
{
    db::files::removeStaleTemporaries(path); // what a killed writer left
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return Error(Error::Kind::Io,
                     tr("cannot write %1: %2").arg(QFileInfo(path).fileName(), file.errorString()));
    const QByteArray bytes = toCsv().toUtf8();
    if (file.write(bytes) != bytes.size() || !file.commit())
        return Error(Error::Kind::Io,
                     tr("cannot write %1: %2").arg(QFileInfo(path).fileName(), file.errorString()));
    return {};
}

} // namespace db
