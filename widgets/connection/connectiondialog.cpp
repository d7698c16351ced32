#include "connectiondialog.h"

#include "widgets/common/widgetstyle.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace db::widgets {

ConnectionDialog::ConnectionDialog(const ProtocolRegistry &registry, const QStringList &recent,
                                   QWidget *parent)
    : QDialog(parent)
    , m_registry(registry)
    , m_recent(recent)
    , m_protocol(new QComboBox(this))
    , m_patternHint(new QLabel(this))
    , m_hostBox(new QComboBox(this))
    , m_host(new QLineEdit(this))
    , m_port(new QSpinBox(this))
    , m_options(new QLineEdit(this))
    , m_uri(new QLineEdit(this))
    , m_error(new QLabel(this))
    , m_recentList(new QListWidget(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("Connect to Device"));
    m_protocol->setObjectName(QStringLiteral("protocol"));
    m_host->setObjectName(QStringLiteral("host"));
    m_port->setObjectName(QStringLiteral("port"));
    m_options->setObjectName(QStringLiteral("options"));
    m_uri->setObjectName(QStringLiteral("uri"));
    m_error->setObjectName(QStringLiteral("error"));
    m_recentList->setObjectName(QStringLiteral("recent"));

    for (const ProtocolInfo &info : registry.protocols())
        m_protocol->addItem(info.title, info.scheme);

    m_patternHint->setFont(style::monospaceFont());
    style::setTextColor(m_patternHint, style::inactiveColor());
    m_host->setPlaceholderText(tr("IP address, host name or CAN interface"));
    m_hostBox->setObjectName(QStringLiteral("hostBox"));
    m_hostBox->setEditable(true);
    m_hostBox->setLineEdit(m_host); // typed freely; the list offers the CAN interfaces
    m_hostBox->setInsertPolicy(QComboBox::NoInsert);
    m_port->setRange(0, 65535);
    m_options->setPlaceholderText(tr("e.g. node=50&bitrate=500000"));
    m_uri->setFont(style::monospaceFont());
    m_uri->setPlaceholderText(tr("scheme://host[:port][?key=value]"));
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    style::setTextColor(m_error, style::errorColor());
    m_recentList->setFont(style::monospaceFont());
    m_recentList->addItems(m_recent);

    auto *fields = new QGroupBox(tr("Device"), this);
    m_form = new QFormLayout(fields);
    m_form->addRow(tr("&Protocol:"), m_protocol);
    m_form->addRow(QString(), m_patternHint);
    m_form->addRow(tr("&Address:"), m_hostBox);
    m_form->addRow(tr("P&ort:"), m_port);
    createCanopenFields();
    m_form->addRow(tr("O&ptions:"), m_options);
    m_form->addRow(tr("&URI:"), m_uri);
    m_form->addRow(QString(), m_error);

    auto *recentBox = new QGroupBox(tr("Recent connections"), this);
    auto *recentLayout = new QVBoxLayout(recentBox);
    recentLayout->addWidget(m_recentList);
    recentBox->setVisible(!m_recent.isEmpty());

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(fields);
    layout->addWidget(recentBox, 1);
    layout->addWidget(m_buttons);

    connect(m_protocol, &QComboBox::currentIndexChanged, this, [this] {
        onProtocolChanged();
        buildUriFromFields();
    });
    connect(m_host, &QLineEdit::textEdited, this, &ConnectionDialog::buildUriFromFields);
    connect(m_hostBox, &QComboBox::textActivated, this, &ConnectionDialog::buildUriFromFields);
    connect(m_port, &QSpinBox::valueChanged, this, &ConnectionDialog::buildUriFromFields);
    connect(m_options, &QLineEdit::textEdited, this, &ConnectionDialog::buildUriFromFields);
    connect(m_uri, &QLineEdit::textChanged, this, [this] {
        if (!m_updating)
            fillFieldsFromUri();
        validate();
    });
    connect(m_recentList, &QListWidget::currentTextChanged, this, [this](const QString &text) {
        if (!text.isEmpty())
            setUri(text);
    });
    connect(m_recentList, &QListWidget::itemActivated, this, [this] {
        if (isValid())
            accept();
    });
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    onProtocolChanged();
    if (!m_recent.isEmpty())
        setUri(m_recent.first());
    else
        validate();
    resize(560, sizeHint().height());
}

void ConnectionDialog::accept()
{
    if (!isValid())
        return;
    auto plan = m_registry.prepare(m_validUri);
    if (!plan) {
        m_error->setText(plan.error().message());
        style::setTextColor(m_error, style::errorColor());
        return;
    }
    m_plan = std::move(plan).value();
    QDialog::accept();
}

QString ConnectionDialog::uri() const
{
    return m_validUri;
}

QString ConnectionDialog::errorText() const
{
    return m_error->text();
}

void ConnectionDialog::setUri(const QString &uri)
{
    m_uri->setText(uri); // textChanged fills the fields and validates
}

QStringList ConnectionDialog::recentUris() const
{
    return isValid() ? withRecent(m_recent, m_validUri) : m_recent;
}

QStringList ConnectionDialog::withRecent(QStringList recent, const QString &uri)
{
    recent.removeAll(uri);
    recent.prepend(uri);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    return recent;
}

void ConnectionDialog::onProtocolChanged()
{
    const ProtocolInfo *info = m_registry.find(m_protocol->currentData().toString());
    m_patternHint->setText(info ? info->uriPattern : QString());
    const bool hasPort = info && info->defaultPort >= 0;
    const QSignalBlocker blocker(m_port);
    m_port->setEnabled(hasPort);
    m_port->setValue(hasPort ? info->defaultPort : 0);
    m_port->setSpecialValueText(hasPort ? QString() : tr("none"));
    m_form->setRowVisible(m_port, hasPort); // a CAN interface has no port
    updateCanopenFields(info);
}

void ConnectionDialog::buildUriFromFields()
{
    if (m_updating)
        return;
    const QString scheme = m_protocol->currentData().toString();
    const ProtocolInfo *info = m_registry.find(scheme);
    QString text = scheme + QStringLiteral("://") + m_host->text().trimmed();
    if (info && info->defaultPort >= 0)
        text += QLatin1Char(':') + QString::number(m_port->value());
    const QString options = m_options->text().trimmed();
    if (!options.isEmpty())
        text += QLatin1Char('?') + options;
    if (m_host->text().trimmed().isEmpty())
        text.clear(); // "Enter an address" rather than a syntax error
    m_updating = true;
    m_uri->setText(text);
    m_updating = false;
}

void ConnectionDialog::fillFieldsFromUri()
{
    // Best effort: the free line stays the truth; the fields follow when it parses.
    auto parsed = ConnectionUri::parse(m_uri->text());
    if (!parsed)
        return;
    m_updating = true;
    const int index = m_protocol->findData(parsed->scheme());
    if (index >= 0 && index != m_protocol->currentIndex()) {
        m_protocol->setCurrentIndex(index);
        onProtocolChanged();
    }
    m_host->setText(parsed->host());
    // No port in the URI: the protocol's own (RefGo 10001, ...), not the one a recent
    // connection left in the field (which the URI would not use).
    const ProtocolInfo *info = m_registry.find(parsed->scheme());
    if (m_port->isEnabled())
        m_port->setValue(parsed->port() >= 0                  ? parsed->port()
                             : info && info->defaultPort >= 0 ? info->defaultPort
                                                              : m_port->value());
    fillCanopenFields(*parsed);
    QStringList options;
    const auto query = parsed->query();
    for (auto it = query.cbegin(); it != query.cend(); ++it)
        options.append(it.key() + QLatin1Char('=') + it.value());
    m_options->setText(options.join(QLatin1Char('&')));
    m_updating = false;
}

void ConnectionDialog::validate()
{
    const QString text = m_uri->text().trimmed();
    m_validUri.clear();
    if (text.isEmpty()) {
        m_error->setText(tr("Enter an address or a connection URI."));
        style::setTextColor(m_error, style::inactiveColor());
    } else if (auto parsed = m_registry.parseUri(text); parsed) {
        m_validUri = parsed->toString();
        m_error->setText(tr("Connects to %1").arg(m_validUri));
        style::setTextColor(m_error, style::okColor());
    } else {
        m_error->setText(parsed.error().message());
        style::setTextColor(m_error, style::errorColor());
    }
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(isValid());
}

} // namespace db::widgets
