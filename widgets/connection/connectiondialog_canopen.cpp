// The CANopen fields of the connection dialog: interfaces of the Qt CAN plugin, node id, bit
// rate and description. They edit the options line (node=, bitrate=, eds=), which stays the
// truth together with the URI line.
#include "canopen/canbusfactory.h"
#include "connectiondialog.h"
#include "widgets/odeditor/descriptionprompt.h"

#include <algorithm>

#include <QCanBus>
#include <QComboBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

namespace db::widgets {

namespace {

const QString kCanopenKey = QStringLiteral("canopen");
const QString kCanopenPrefix = QStringLiteral("canopen+");
const QString kSlcan = QStringLiteral("slcan");
const QString kBrowse = QStringLiteral("\x01browse"); // data of the "Other file…" item

// The Qt CAN plugin of a scheme ("canopen+virtualcan" -> "virtualcan"); empty for SLCAN (our own
// transport over TCP) and for every scheme that is not CANopen (CanBusFactory's naming).
QString canPluginOf(const ProtocolInfo *info)
{
    if (!info || info->key != kCanopenKey || !info->scheme.startsWith(kCanopenPrefix))
        return {};
    const QString transport = info->scheme.mid(kCanopenPrefix.size());
    return transport == kSlcan ? QString() : transport;
}

} // namespace

void ConnectionDialog::createCanopenFields()
{
    m_node = new QSpinBox(this);
    m_node->setObjectName(QStringLiteral("node"));
    m_node->setRange(0, 127);
    m_node->setSpecialValueText(tr("not set"));
    m_node->setToolTip(tr("CANopen node id of the device (1..127)"));

    m_bitrate = new QComboBox(this);
    m_bitrate->setObjectName(QStringLiteral("bitrate"));
    m_bitrate->addItem(QString(), 0); // text set per protocol
    for (const int kbit : { 1000, 800, 500, 250, 125, 100, 50, 20, 10 })
        m_bitrate->addItem(tr("%1 kbit/s").arg(kbit), kbit * 1000);

    m_description = new QComboBox(this);
    m_description->setObjectName(QStringLiteral("description"));
    m_description->addItem(tr("Automatic by identity (1018h)"), QString());
    m_description->addItem(tr("Other file…"), kBrowse);
    m_description->setToolTip(
        tr("Automatic: the description library's file for the vendor, product and revision the "
           "node reports. Or a description file for this connection."));

    m_form->addRow(tr("&Node:"), m_node);
    m_form->addRow(tr("&Bit rate:"), m_bitrate);
    m_form->addRow(tr("&Description:"), m_description);
    setAcceptDrops(true); // a description file dropped onto the dialog

    connect(m_node, &QSpinBox::valueChanged, this, [this](int node) {
        if (!m_updating)
            setOption(QStringLiteral("node"), node > 0 ? QString::number(node) : QString());
    });
    connect(m_bitrate, &QComboBox::activated, this, [this](int index) {
        const int bitrate = m_bitrate->itemData(index).toInt();
        setOption(QStringLiteral("bitrate"), bitrate > 0 ? QString::number(bitrate) : QString());
    });
    connect(m_description, &QComboBox::activated, this, [this](int index) {
        const QString path = m_description->itemData(index).toString();
        if (path == kBrowse)
            chooseDescriptionFile();
        else
            setOption(QStringLiteral("eds"), path);
    });
}

void ConnectionDialog::setDescriptionEntries(const QList<LibraryEntry> &entries)
{
    for (const LibraryEntry &entry : entries) {
        if (!QFileInfo(entry.origin).isFile() || descriptionIndexOf(entry.origin) >= 0)
            continue;
        const int at = m_description->count() - 1; // before "Other file…"
        m_description->insertItem(
            at, tr("%1 (%2)").arg(entry.name, QFileInfo(entry.origin).fileName()), entry.origin);
        m_description->setItemData(at, entry.origin, Qt::ToolTipRole);
    }
}

int ConnectionDialog::descriptionIndexOf(const QString &path)
{
    return path.isEmpty() ? 0 : m_description->findData(path);
}

void ConnectionDialog::chooseDescriptionFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Description of the device"),
                                                      QString(), DescriptionPrompt::fileFilter());
    if (path.isEmpty()) { // back to what the URI says
        auto parsed = ConnectionUri::parse(m_uri->text());
        const int index =
            descriptionIndexOf(parsed ? parsed->queryValue(QStringLiteral("eds")) : QString());
        m_description->setCurrentIndex(qMax(0, index));
        return;
    }
    setOption(QStringLiteral("eds"), path);
    selectDescription(path);
}

bool ConnectionDialog::useDroppedDescription(const QString &path)
{
    if (path.isEmpty() || !m_description->isVisibleTo(this))
        return false; // only a CANopen connection takes a description file
    setOption(QStringLiteral("eds"), path);
    selectDescription(path);
    return true;
}

void ConnectionDialog::dragEnterEvent(QDragEnterEvent *event)
{
    if (m_description->isVisibleTo(this)
        && !DescriptionPrompt::droppedDescription(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void ConnectionDialog::dropEvent(QDropEvent *event)
{
    if (useDroppedDescription(DescriptionPrompt::droppedDescription(event->mimeData())))
        event->acceptProposedAction();
}

void ConnectionDialog::updateCanopenFields(const ProtocolInfo *info)
{
    const bool canopen = info && info->key == kCanopenKey;
    const QString plugin = canPluginOf(info);
    m_form->setRowVisible(m_node, canopen);
    m_form->setRowVisible(m_bitrate, canopen);
    m_form->setRowVisible(m_description, canopen);
    if (auto *label = qobject_cast<QLabel *>(m_form->labelForField(m_hostBox)))
        label->setText(plugin.isEmpty() ? tr("&Address:") : tr("&Interface:"));
    m_bitrate->setItemText(
        0,
        plugin.isEmpty()
            ? tr("default (%1 kbit/s)").arg(canopen::CanBusFactory::kDefaultSlcanBitrate / 1000)
            : tr("as the interface is set"));

    // The interfaces the plugin reports; what the user typed stays unless it is none of them
    // and looks like a network address (the previous protocol's host).
    const QString text = m_host->text();
    const bool wasUpdating = m_updating;
    m_updating = true;
    m_hostBox->clear();
    if (!plugin.isEmpty()) {
        QString error;
        const QList<QCanBusDeviceInfo> devices =
            QCanBus::instance()->availableDevices(plugin, &error);
        for (const QCanBusDeviceInfo &device : devices) {
            m_hostBox->addItem(device.name());
            if (!device.description().isEmpty())
                m_hostBox->setItemData(m_hostBox->count() - 1, device.description(),
                                       Qt::ToolTipRole);
        }
        QStringList names;
        for (const QCanBusDeviceInfo &device : devices)
            names.append(device.name());
        m_host->setPlaceholderText(
            names.isEmpty()
                ? (error.isEmpty() ? tr("no interface found; type its name")
                                   : tr("no interface found (%1); type its name").arg(error))
                : tr("choose an interface: %1").arg(names.join(QStringLiteral(", "))));
        m_hostBox->setCurrentIndex(-1);
        const bool networkAddress =
            text.contains(QLatin1Char('.')) && !names.contains(text); // "127.0.0.1", "gw.local"
        m_host->setText(networkAddress ? QString() : text);
    } else {
        m_host->setPlaceholderText(canopen ? tr("IP address or host name of the SLCAN gateway")
                                           : tr("IP address or host name"));
        m_hostBox->setCurrentIndex(-1);
        m_host->setText(text);
    }
    m_updating = wasUpdating;
}

void ConnectionDialog::fillCanopenFields(const ConnectionUri &uri)
{
    bool ok = false;
    const int node = uri.queryValue(QStringLiteral("node")).toInt(&ok);
    m_node->setValue(ok && node >= 1 && node <= 127 ? node : 0);
    const int bitrate = uri.queryValue(QStringLiteral("bitrate")).toInt(&ok);
    m_bitrate->setCurrentIndex(qMax(0, m_bitrate->findData(ok ? bitrate : 0)));
    selectDescription(uri.queryValue(QStringLiteral("eds")));
}

void ConnectionDialog::selectDescription(const QString &path)
{
    int index = descriptionIndexOf(path);
    if (index < 0) { // a file of no library entry: offered as a choice of its own
        index = m_description->count() - 1;
        m_description->insertItem(index, QFileInfo(path).fileName(), path);
        m_description->setItemData(index, path, Qt::ToolTipRole);
    }
    m_description->setCurrentIndex(index);
}

void ConnectionDialog::setOption(const QString &key, const QString &value)
{
    QStringList options = m_options->text().split(QLatin1Char('&'), Qt::SkipEmptyParts);
    const QString prefix = key + QLatin1Char('=');
    const auto it = std::find_if(options.begin(), options.end(),
                                 [&](const QString &o) { return o.trimmed().startsWith(prefix); });
    if (value.isEmpty()) {
        if (it != options.end())
            options.erase(it);
    } else if (it != options.end()) {
        *it = prefix + value;
    } else {
        options.append(prefix + value);
    }
    m_options->setText(options.join(QLatin1Char('&')));
    buildUriFromFields();
}

} // namespace db::widgets
