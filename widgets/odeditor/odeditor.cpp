#include "odeditor.h"

#include "core/changelog.h"
#include "description/devicedescription.h"
#include "descriptionprompt.h"
#include "objectaccessbox.h"
#include "odeditorbits.h"
#include "odeditordelegate.h"
#include "odeditorfilter.h"
#include "odeditormodel.h"
#include "odeditorpoller.h"
#include "widgets/common/flowlayout.h"
#include "widgets/common/widgetstyle.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollBar>
#include <QSplitter>
#include <QToolButton>
#include <QTreeView>
#include <QVBoxLayout>

namespace db::widgets {

namespace {
constexpr int kDefaultPeriodMs = 1000;

QString periodName(int ms)
{
    if (ms == 0)
        return OdEditor::tr("Off");
    if (ms < 1000)
        return OdEditor::tr("%1 ms").arg(ms);
    return OdEditor::tr("%1 s").arg(ms / 1000);
}
} // namespace

OdEditor::OdEditor(QWidget *parent)
    : QWidget(parent)
    , m_model(new OdEditorModel(this))
    , m_filter(new OdEditorFilter(this))
    , m_poller(new OdEditorPoller(m_model, this))
    , m_delegate(new OdEditorDelegate(m_model, this))
    , m_filterEdit(new QLineEdit(this))
    , m_hex(new QCheckBox(tr("He&x"), this))
    , m_ram(new QCheckBox(tr("Write to RAM"), this))
    , m_rate(new QComboBox(this))
    , m_tools(new FlowLayout)
    , m_view(new QTreeView(this))
    , m_details(new OdBitFieldView(this))
    , m_counts(new QLabel(this))
    , m_status(new QLabel(this))
    , m_prompt(new DescriptionPrompt(this))
{
    m_filterEdit->setObjectName(QStringLiteral("filter"));
    m_hex->setObjectName(QStringLiteral("hex"));
    m_ram->setObjectName(QStringLiteral("ramWrites"));
    m_ram->setToolTip(tr("Edits change the working value only: lost at power-off, the EEPROM is "
                         "not written. Off: edits are stored permanently in the data set."));
    m_ram->hide();
    m_rate->setObjectName(QStringLiteral("refreshRate"));
    m_view->setObjectName(QStringLiteral("objects"));
    m_status->setObjectName(QStringLiteral("status"));
    m_counts->setObjectName(QStringLiteral("counts"));

    m_filter->setSourceModel(m_model);
    m_filterEdit->setPlaceholderText(tr("Filter by index, name or value (e.g. 6041, velocity)"));
    m_filterEdit->setClearButtonEnabled(true);
    m_filterEdit->setMinimumWidth(140);
    for (int ms : OdEditorPoller::kPeriodsMs)
        m_rate->addItem(periodName(ms), ms);
    m_rate->setToolTip(tr("Live refresh of the rows on screen"));
    auto *readAllButton = new QToolButton(this);
    readAllButton->setObjectName(QStringLiteral("readAll"));
    readAllButton->setText(tr("Read all"));
    readAllButton->setToolTip(tr("Read every object of the device once"));
    auto *byIndexButton = new QToolButton(this);
    byIndexButton->setObjectName(QStringLiteral("byIndex"));
    byIndexButton->setText(tr("By index…"));
    byIndexButton->setToolTip(tr("Read or write an object the device description does not list"));

    m_tools->addWidget(m_filterEdit); // expanding: takes the room left in its row
    m_tools->addWidget(m_hex);
    m_tools->addWidget(m_ram);
    // The label stays with its box when the row wraps.
    auto *rate = new QWidget(this);
    auto *rateRow = new QHBoxLayout(rate);
    rateRow->setContentsMargins(0, 0, 0, 0);
    rateRow->addWidget(new QLabel(tr("Refresh:"), rate));
    rateRow->addWidget(m_rate);
    m_tools->addWidget(rate);
    m_tools->addWidget(readAllButton);
    // Read all: how far it got, and a way to stop it on a slow link.
    auto *readProgress = new QProgressBar(this);
    readProgress->setObjectName(QStringLiteral("readAllProgress"));
    readProgress->setMaximumWidth(160);
    readProgress->setFormat(tr("%v of %m"));
    readProgress->hide();
    auto *cancelRead = new QToolButton(this);
    cancelRead->setObjectName(QStringLiteral("cancelReadAll"));
    cancelRead->setText(tr("Cancel"));
    cancelRead->setToolTip(tr("Stop reading every object (values read so far stay)"));
    cancelRead->hide();
    m_tools->addWidget(readProgress);
    m_tools->addWidget(cancelRead);
    connect(cancelRead, &QToolButton::clicked, m_poller, &OdEditorPoller::cancelReadAll);
    connect(m_poller, &OdEditorPoller::readAllProgress, this,
            [readProgress, cancelRead](int done, int total) {
                readProgress->setRange(0, qMax(1, total));
                readProgress->setValue(done);
                readProgress->setVisible(total > 0);
                cancelRead->setVisible(total > 0);
            });
    m_tools->addWidget(byIndexButton);

    m_view->setModel(m_filter);
    m_view->setItemDelegateForColumn(OdEditorModel::Value, m_delegate);
    m_view->setUniformRowHeights(true);
    m_view->setAlternatingRowColors(true);
    m_view->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::SelectedClicked);
    m_view->setDragEnabled(true);
    m_view->setDragDropMode(QAbstractItemView::DragOnly);
    m_view->setAllColumnsShowFocus(true);
    QHeaderView *header = m_view->header();
    // Stable widths: every column keeps the width it starts with (or the user gives it); the
    // last one takes the room that is left, and a narrow window scrolls sideways rather than
    // squeezing the names to "P…".
    header->setStretchLastSection(true);
    header->setSectionResizeMode(QHeaderView::Interactive);
    const QFontMetrics mono(style::monospaceFont());
    const int ch = mono.horizontalAdvance(QLatin1Char('0'));
    header->resizeSection(OdEditorModel::Address, ch * 10 + 40);
    header->resizeSection(OdEditorModel::Name, kNameColumnWidth);
    header->resizeSection(OdEditorModel::Unit,
                          fontMetrics().horizontalAdvance(QStringLiteral("rpm/s²")) + 16);
    header->resizeSection(OdEditorModel::Type,
                          fontMetrics().horizontalAdvance(QStringLiteral("VISIBLE_STRING")) + 16);
    header->resizeSection(OdEditorModel::AccessColumn,
                          fontMetrics().horizontalAdvance(QStringLiteral("Access")) + 20);
    header->resizeSection(OdEditorModel::Value, ch * 28);
    header->resizeSection(OdEditorModel::Default, ch * 14);
    header->resizeSection(OdEditorModel::Limits, ch * 22);
    header->resizeSection(OdEditorModel::Pdo,
                          fontMetrics().horizontalAdvance(QStringLiteral("PDO")) + 24);

    auto *splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_view);
    splitter->addWidget(m_details);
    splitter->setStretchFactor(0, 4);
    splitter->setStretchFactor(1, 1);
    splitter->setChildrenCollapsible(false);

    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_counts->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    style::setTextColor(m_counts, style::inactiveColor());
    auto *statusRow = new QHBoxLayout;
    statusRow->addWidget(m_status, 1);
    statusRow->addWidget(m_counts);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(m_tools);
    layout->addWidget(m_prompt);
    layout->addWidget(splitter, 1);
    layout->addLayout(statusRow);

    connect(m_filterEdit, &QLineEdit::textChanged, this, [this](const QString &text) {
        m_filter->setText(text);
        if (!text.isEmpty())
            m_view->expandAll();
        updateCounts();
    });
    connect(m_hex, &QCheckBox::toggled, m_model, &OdEditorModel::setHex);
    connect(m_hex, &QCheckBox::toggled, this, [this] { onCurrentChanged(); });
    connect(m_rate, &QComboBox::currentIndexChanged, this,
            [this] { m_poller->setPeriodMs(m_rate->currentData().toInt()); });
    connect(readAllButton, &QToolButton::clicked, this, &OdEditor::readAll);
    connect(m_prompt, &DescriptionPrompt::fileChosen, this, &OdEditor::useDescriptionFile);
    connect(byIndexButton, &QToolButton::clicked, this, &OdEditor::showAccessByIndex);
    connect(m_model, &OdEditorModel::writeRequested, this, &OdEditor::onWriteRequested);
    connect(m_model, &OdEditorModel::editRefused, this,
            [this](ObjectAddress a, const QString &reason) {
                showStatus(tr("%1 not written: %2").arg(a.toString(), reason), style::errorColor());
            });
    connect(m_delegate, &OdEditorDelegate::inputProblem, this, [this](const QString &problem) {
        if (!problem.isEmpty())
            showStatus(problem, style::errorColor());
    });
    connect(m_model, &QAbstractItemModel::dataChanged, this, &OdEditor::onModelDataChanged);
    // Group titles span the whole row; spans are per proxy row, so renew them when rows change.
    const auto spanGroups = [this] {
        for (int row = 0; row < m_filter->rowCount(); ++row)
            m_view->setFirstColumnSpanned(row, QModelIndex(), true);
    };
    connect(m_filter, &QAbstractItemModel::modelReset, this, spanGroups);
    connect(m_filter, &QAbstractItemModel::layoutChanged, this, spanGroups);
    connect(m_filter, &QAbstractItemModel::rowsInserted, this, spanGroups);
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        arrangeColumns();
        m_view->expandToDepth(0);
        onCurrentChanged();
        updateCounts();
    });
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &OdEditor::onCurrentChanged);
    // The rows on screen and the selected object (its bits are in the details pane).
    m_poller->setVisibleRows([this] {
        if (!isVisible())
            return QList<ObjectAddress>();
        QList<ObjectAddress> rows = visibleAddresses();
        const auto current = m_model->addressAt(m_filter->mapToSource(m_view->currentIndex()));
        if (current && !rows.contains(*current))
            rows.append(*current);
        return rows;
    });
    setRefreshPeriodMs(kDefaultPeriodMs);
    setConnection(nullptr);
}

OdEditor::~OdEditor()
{
    disconnect(m_stateConnection);
    disconnect(m_dictionaryConnection);
    // An editor still open is committed while the view dies: that must not write anything.
    disconnect(m_model, nullptr, this, nullptr);
    disconnect(m_delegate, nullptr, this, nullptr);
    m_model->setEditable(false);
}

void OdEditor::setConnection(DeviceConnection *connection)
{
    if (connection && connection == m_connection)
        return;
    disconnect(m_stateConnection);
    disconnect(m_dictionaryConnection);
    ++m_generation;
    m_poller->setConnection(connection);
    m_connection = connection;
    m_model->setAddressFormat(connection ? &connection->addressFormat() : nullptr);
    m_details->setAddressFormat(connection ? connection->addressFormat()
                                           : AddressFormat::canopen());
    m_model->setDictionary(connection ? connection->dictionary() : ObjectDictionary());
    m_ram->setChecked(false);
    m_ram->setVisible(connection && connection->ramAddress(ObjectAddress(1, 1)).has_value());
    if (connection) {
        m_stateConnection =
            connect(connection, &DeviceConnection::stateChanged, this, &OdEditor::onStateChanged);
        m_dictionaryConnection = connect(connection, &DeviceConnection::dictionaryChanged, this,
                                         &OdEditor::onDictionaryChanged);
    }
    showStatus(connection ? QString() : tr("No device"));
    onStateChanged();
}

void OdEditor::onStateChanged()
{
    const bool connected = m_connection && m_connection->isConnected();
    m_model->setEditable(connected);
    m_prompt->showFor(m_connection);
    if (!connected) {
        m_poller->clear();
        return;
    }
    // Descriptions may be swapped by the connection (e.g. after reading the identity).
    const ObjectDictionary &dict = m_connection->dictionary();
    if (dict.size() != m_model->dictionary().size()
        || dict.identity.descriptionFile != m_model->dictionary().identity.descriptionFile)
        m_model->setDictionary(dict);
    readAll();
}

void OdEditor::onDictionaryChanged()
{
    if (!m_connection)
        return;
    m_model->setDictionary(m_connection->dictionary());
    m_prompt->showFor(m_connection);
    if (m_connection->isConnected())
        readAll();
}

bool OdEditor::useDescriptionFile(const QString &path)
{
    if (!m_connection)
        return false;
    DescriptionOptions options;
    const int node = m_connection->networkAddress();
    if (node >= 1 && node <= 127)
        options.nodeId = quint8(node);
    auto loaded = loadDeviceDescription(path, options);
    if (!loaded) {
        m_prompt->showProblem(tr("%1 cannot be used: %2").arg(path, loaded.error().message()));
        return false;
    }
    m_connection->setDictionary(loaded->dictionary);
    showStatus(tr("Description: %1").arg(path));
    Q_EMIT descriptionFileUsed(path);
    return true;
}

void OdEditor::readAll()
{
    m_poller->readNow(visibleAddresses(), true);
    m_poller->readAll();
}

void OdEditor::addToolActions(const QString &title, const QList<QAction *> &actions)
{
    // One drop-down button, so that the tool row fits a laptop screen next to the docks. A push
    // button draws its menu arrow beside the text (a tool button's would cover it).
    auto *button = new QPushButton(title, this);
    button->setObjectName(QStringLiteral("toolMenu"));
    auto *menu = new QMenu(button);
    menu->addActions(actions);
    button->setMenu(menu);
    m_tools->addWidget(button);
}

void OdEditor::focusFilter()
{
    m_filterEdit->setFocus(Qt::ShortcutFocusReason);
    m_filterEdit->selectAll();
}

void OdEditor::setFilterText(const QString &text)
{
    m_filterEdit->setText(text);
}

void OdEditor::setHex(bool hex)
{
    m_hex->setChecked(hex);
}

void OdEditor::setRefreshPeriodMs(int ms)
{
    int best = 0;
    for (int i = 0; i < m_rate->count(); ++i) {
        if (qAbs(m_rate->itemData(i).toInt() - ms) < qAbs(m_rate->itemData(best).toInt() - ms))
            best = i;
    }
    m_rate->setCurrentIndex(best);
    m_poller->setPeriodMs(m_rate->itemData(best).toInt());
}

int OdEditor::refreshPeriodMs() const
{
    return m_poller->periodMs();
}

QString OdEditor::statusText() const
{
    return m_status->text();
}

QList<ObjectAddress> OdEditor::visibleAddresses() const
{
    QList<ObjectAddress> result;
    const int bottom = m_view->viewport()->height();
    for (QModelIndex i = m_view->indexAt(QPoint(1, 1)); i.isValid(); i = m_view->indexBelow(i)) {
        if (m_view->visualRect(i).top() > bottom)
            break;
        result.append(m_model->valueAddressesAt(m_filter->mapToSource(i)));
    }
    return result;
}

void OdEditor::setWritesToRam(bool ram)
{
    m_ram->setChecked(ram);
}

bool OdEditor::writesToRam() const
{
    return m_ram->isChecked() && m_ram->isVisibleTo(this);
}

void OdEditor::arrangeColumns()
{
    QHeaderView *header = m_view->header();
    // Parameter lists have no PDOs; their five value columns need the room of type and
    // default (both stay in the details pane).
    for (int column : { OdEditorModel::Pdo, OdEditorModel::Type, OdEditorModel::Default })
        header->setSectionHidden(column, m_model->hasDataSetColumns());
    if (!m_model->hasDataSetColumns())
        return;
    const int ch = QFontMetrics(style::monospaceFont()).horizontalAdvance(QLatin1Char('0'));
    for (int k = 0; k < 4; ++k) {
        const int column = OdEditorModel::DataSet1 + k;
        header->moveSection(header->visualIndex(column),
                            header->visualIndex(OdEditorModel::Value) + 1 + k);
        header->resizeSection(column, ch * 12);
        m_view->setItemDelegateForColumn(column, m_delegate);
    }
    header->resizeSection(OdEditorModel::Value, ch * 12);
}

void OdEditor::onWriteRequested(ObjectAddress address, const QVariant &raw)
{
    if (!m_connection || !m_connection->isConnected()) {
        m_model->setWriteFinished(address, false, tr("not connected"));
        return;
    }
    const ObjectDef *def = m_model->definition(address);
    const QVariant before = m_model->value(address);
    m_model->setWriting(address, raw);
    // RAM: the same parameter at its working-memory address; the cell is the data set's.
    const auto ram = writesToRam() ? m_connection->ramAddress(address) : std::nullopt;
    Reply *reply = m_connection->write(ram.value_or(address), raw);
    reply->setParent(this);
    if (m_changeLog) {
        const auto text = [def](const QVariant &v) {
            return !v.isValid() ? QString()
                : def           ? odtext::display(*def, v, false, true, true)
                                : v.toString();
        };
        m_changeLog->track(ChangeLog::writeEntry(*m_connection, ram.value_or(address), text(before),
                                                 text(raw), ram.has_value()),
                           reply);
    }
    const quint64 generation = m_generation;
    QString shown = m_model->data(m_model->indexOf(address, OdEditorModel::Name)).toString();
    if (ram)
        shown += QLatin1Char(' ')
            + tr("to RAM (%1, lost at power-off)").arg(m_model->addressFormat().format(*ram));
    showStatus(tr("Writing %1 %2…").arg(m_model->addressFormat().format(address), shown));
    connect(reply, &Reply::finished, this, [this, reply, generation, address, shown] {
        reply->deleteLater();
        if (generation != m_generation)
            return;
        const QString message = reply->ok() ? QString() : reply->error().toString();
        m_model->setWriteFinished(address, reply->ok(), message);
        if (reply->ok()) {
            showStatus(tr("%1 %2 written").arg(m_model->addressFormat().format(address), shown),
                       style::okColor());
            m_poller->readNow({ address }); // verify: show what the device really holds
        } else {
            showStatus(
                tr("%1 %2: %3").arg(m_model->addressFormat().format(address), shown, message),
                style::errorColor());
        }
        Q_EMIT writeFinished(address, reply->ok(), message);
    });
}

void OdEditor::onCurrentChanged()
{
    const auto a = m_model->addressAt(m_filter->mapToSource(m_view->currentIndex()));
    const ObjectDef *def = a ? m_model->definition(*a) : nullptr;
    m_details->setObject(def);
    if (def)
        m_details->setValue(m_model->value(*a));
}

void OdEditor::onModelDataChanged(const QModelIndex &topLeft, const QModelIndex &)
{
    const auto a = m_model->addressAt(topLeft);
    const auto current = m_model->addressAt(m_filter->mapToSource(m_view->currentIndex()));
    if (a && current && *a == *current)
        m_details->setValue(m_model->value(*a));
}

void OdEditor::showStatus(const QString &text, const QColor &color)
{
    m_status->setText(text);
    m_status->setToolTip(text);
    style::setTextColor(m_status, color);
}

void OdEditor::updateCounts()
{
    const int total = int(m_model->addresses().size());
    m_counts->setText(m_filter->text().isEmpty() ? tr("%n object(s)", nullptr, total)
                                                 : tr("filter: %1").arg(m_filter->text()));
}

void OdEditor::showAccessByIndex()
{
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Read/Write by Index"));
    auto *box = new ObjectAccessBox(&dialog);
    box->setConnection(m_connection);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, &dialog);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    auto *layout = new QVBoxLayout(&dialog);
    layout->addWidget(new QLabel(tr("Objects that the device description does not list are "
                                    "added to the tree once read or written."),
                                 &dialog));
    layout->addWidget(box);
    layout->addWidget(buttons);
    connect(box, &ObjectAccessBox::finished, this, [this, box](bool ok) {
        const auto def = box->currentDefinition();
        if (!ok || !def || m_model->definition(def->address))
            return;
        m_model->addExtraObject(*def);
        m_poller->readNow({ def->address });
    });
    dialog.resize(460, 280);
    dialog.exec();
}

} // namespace db::widgets
