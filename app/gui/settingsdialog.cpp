#include "settingsdialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace db::gui {

namespace {
constexpr int kMinTimeoutMs = 50;
constexpr int kMaxTimeoutMs = 60000;

QSpinBox *milliseconds(const QString &name, int value, QWidget *parent)
{
    auto *box = new QSpinBox(parent);
    box->setObjectName(name);
    box->setRange(kMinTimeoutMs, kMaxTimeoutMs);
    box->setSingleStep(100);
    box->setSuffix(QStringLiteral(" ms"));
    box->setValue(value);
    return box;
}
} // namespace

SettingsDialog::SettingsDialog(const Values &values, QWidget *parent)
    : QDialog(parent)
    , m_language(new QComboBox(this))
    , m_connectTimeout(
          milliseconds(QStringLiteral("connectTimeout"), values.connectTimeoutMs, this))
    , m_requestTimeout(
          milliseconds(QStringLiteral("requestTimeout"), values.requestTimeoutMs, this))
    , m_autoReconnect(new QCheckBox(tr("Reconnect automatically after a lost connection"), this))
    , m_reconnectWindow(new QSpinBox(this))
    , m_recent(new QListWidget(this))
{
    setWindowTitle(tr("Settings"));
    m_language->setObjectName(QStringLiteral("language"));
    m_language->addItem(tr("As the system"), QString());
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    m_language->setCurrentIndex(qMax(0, m_language->findData(values.language)));
    auto *languageNote = new QLabel(tr("Takes effect at the next start."), this);
    languageNote->setEnabled(false);

    m_connectTimeout->setToolTip(tr("How long a new connection may take to reach the device"));
    m_requestTimeout->setToolTip(tr("How long a read or write waits for the device's answer"));

    m_autoReconnect->setObjectName(QStringLiteral("autoReconnect"));
    m_autoReconnect->setChecked(values.autoReconnect);
    m_autoReconnect->setToolTip(
        tr("When a link that was up goes down (not when you disconnect), it is opened again "
           "every few seconds until the device is back or the time below has passed. Each "
           "attempt is shown in the log."));
    m_reconnectWindow->setObjectName(QStringLiteral("reconnectWindow"));
    m_reconnectWindow->setRange(5, 3600);
    m_reconnectWindow->setSuffix(QStringLiteral(" s"));
    m_reconnectWindow->setValue(values.reconnectWindowS);
    m_reconnectWindow->setEnabled(values.autoReconnect);
    connect(m_autoReconnect, &QCheckBox::toggled, m_reconnectWindow, &QWidget::setEnabled);

    m_recent->setObjectName(QStringLiteral("recent"));
    m_recent->addItems(values.recent);
    m_recent->setSelectionMode(QAbstractItemView::ExtendedSelection);
    auto *remove = new QPushButton(tr("Remove"), this);
    remove->setObjectName(QStringLiteral("removeRecent"));
    auto *clear = new QPushButton(tr("Clear All"), this);
    clear->setObjectName(QStringLiteral("clearRecent"));
    connect(remove, &QPushButton::clicked, this, [this] { qDeleteAll(m_recent->selectedItems()); });
    connect(clear, &QPushButton::clicked, m_recent, &QListWidget::clear);

    auto *form = new QFormLayout;
    form->addRow(tr("Language:"), m_language);
    form->addRow(QString(), languageNote);
    form->addRow(tr("Connect time limit:"), m_connectTimeout);
    form->addRow(tr("Answer time limit:"), m_requestTimeout);
    form->addRow(QString(), m_autoReconnect);
    form->addRow(tr("Keep trying for:"), m_reconnectWindow);
    auto *recentBox = new QGroupBox(tr("Recent connections"), this);
    auto *recentButtons = new QHBoxLayout;
    recentButtons->addWidget(remove);
    recentButtons->addWidget(clear);
    recentButtons->addStretch();
    auto *recentLayout = new QVBoxLayout(recentBox);
    recentLayout->addWidget(m_recent);
    recentLayout->addLayout(recentButtons);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(recentBox, 1);
    layout->addWidget(buttons);
}

SettingsDialog::Values SettingsDialog::values() const
{
    Values v;
    v.language = m_language->currentData().toString();
    v.connectTimeoutMs = m_connectTimeout->value();
    v.requestTimeoutMs = m_requestTimeout->value();
    v.autoReconnect = m_autoReconnect->isChecked();
    v.reconnectWindowS = m_reconnectWindow->value();
    for (int row = 0; row < m_recent->count(); ++row)
        v.recent << m_recent->item(row)->text();
    return v;
}

} // namespace db::gui
