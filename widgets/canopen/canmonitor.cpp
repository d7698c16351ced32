#include "canmonitor.h"
#include "core/filewriter.h"

#include "canmonitorlog.h"
#include "canopen/cannetwork.h"
#include "framesender.h"
#include "transport/canbus.h"
#include "widgets/common/flowlayout.h"
#include "widgets/common/quietscrollbar.h"
#include "widgets/common/statictextdelegate.h"
#include "widgets/common/widgetstyle.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QSaveFile>
#include <QTableView>
#include <QToolButton>

namespace db::widgets {

namespace {

QToolButton *makeButton(const QString &text, const QString &toolTip, QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setText(text);
    button->setToolTip(toolTip);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    button->setAutoRaise(true);
    return button;
}

QLineEdit *makeEdit(const QString &name, const QString &placeholder, const QString &toolTip,
                    int chars, QWidget *parent)
{
    auto *edit = new QLineEdit(parent);
    edit->setObjectName(name);
    edit->setPlaceholderText(placeholder);
    edit->setToolTip(toolTip);
    edit->setClearButtonEnabled(true);
    edit->setFont(style::monospaceFont());
    edit->setMinimumWidth(edit->fontMetrics().horizontalAdvance(QLatin1Char('0')) * chars + 30);
    return edit;
}

// Marks an edit whose text does not parse (red, the reason as tool tip) or restores it.
void markInvalid(QLineEdit *edit, const QString &problem, const QString &toolTip)
{
    style::setTextColor(edit, problem.isEmpty() ? QColor() : style::errorColor());
    edit->setToolTip(problem.isEmpty() ? toolTip : problem);
}

} // namespace

CanMonitor::CanMonitor(QWidget *parent)
    : QWidget(parent)
    , m_model(new CanMonitorModel(this))
    , m_filter(new CanMonitorFilter(m_model, this))
    , m_view(new QTableView(this))
    , m_sender(new FrameSender(this))
{
    m_sender->setObjectName(QStringLiteral("frameSender"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    layout->addWidget(createToolBar());
    layout->addWidget(createFilterBar());
    layout->addWidget(m_view, 1);
    layout->addWidget(m_sender);
    setupView();
    connect(m_model, &CanMonitorModel::flushed, this, &CanMonitor::onFlushed);
    updateStatus();
}

CanMonitor::~CanMonitor() = default;

QWidget *CanMonitor::createToolBar()
{
    auto *bar = new QWidget(this);
    auto *row = new QHBoxLayout(bar);
    row->setContentsMargins(0, 0, 0, 0);
    m_pauseButton = makeButton(tr("Pause"),
                               tr("Freeze the table; frames are still captured and appear "
                                  "when you resume"),
                               bar);
    m_pauseButton->setObjectName(QStringLiteral("pause"));
    m_pauseButton->setCheckable(true);
    connect(m_pauseButton, &QToolButton::toggled, this, &CanMonitor::setPaused);
    QToolButton *clearButton = makeButton(tr("Clear"), tr("Forget every frame"), bar);
    clearButton->setObjectName(QStringLiteral("clear"));
    connect(clearButton, &QToolButton::clicked, this, &CanMonitor::clear);
    QToolButton *saveButton =
        makeButton(tr("Save…"), tr("Save the frames shown as a candump log"), bar);
    saveButton->setObjectName(QStringLiteral("save"));
    connect(saveButton, &QToolButton::clicked, this, &CanMonitor::saveLogAs);
    m_autoscroll = new QCheckBox(tr("Autoscroll"), bar);
    m_autoscroll->setObjectName(QStringLiteral("autoscroll"));
    m_autoscroll->setChecked(true);
    m_status = new QLabel(bar);
    m_status->setObjectName(QStringLiteral("status"));
    // Its own background: the count changes with every batch of frames, and a label without one
    // has the dock and the window beneath it repainted each time.
    m_status->setAutoFillBackground(true);
    row->addWidget(m_pauseButton);
    row->addWidget(clearButton);
    row->addWidget(saveButton);
    row->addWidget(m_autoscroll);
    row->addStretch(1);
    row->addWidget(m_status);
    return bar;
}

QWidget *CanMonitor::createFilterBar()
{
    auto *bar = new QWidget(this);
    auto *row = new FlowLayout(bar); // wraps when the monitor is narrow
    row->setContentsMargins(0, 0, 0, 0);
    m_idEdit = makeEdit(QStringLiteral("idFilter"), tr("580-5FF, 81-FF"),
                        tr("COB-IDs in hex: single ids and ranges, comma separated"), 10, bar);
    m_directionBox = new QComboBox(bar);
    m_directionBox->setObjectName(QStringLiteral("directionFilter"));
    m_directionBox->addItem(tr("RX + TX"), int(CanFrameFilter::Direction::Both));
    m_directionBox->addItem(tr("RX"), int(CanFrameFilter::Direction::Rx));
    m_directionBox->addItem(tr("TX"), int(CanFrameFilter::Direction::Tx));
    m_objectEdit = makeEdit(QStringLiteral("objectFilter"), tr("6041"),
                            tr("Object index (hex), optionally :sub-index: SDO traffic of "
                               "this object"),
                            7, bar);
    m_dataEdit = makeEdit(QStringLiteral("dataFilter"), tr("4B 41 60 ?? 27"),
                          tr("Data from byte 0 in hex; ?? matches any byte, ? any digit"), 13, bar);
    m_textEdit = makeEdit(QStringLiteral("textFilter"), tr("Search decoded text"),
                          tr("Text in the service or the CANopen reading"), 10, bar);
    m_textEdit->setFont(font());
    // A label stays with its field when the row wraps.
    const auto labelled = [bar](const QString &text, QWidget *field, QWidget *extra = nullptr) {
        auto *pair = new QWidget(bar);
        auto *layout = new QHBoxLayout(pair);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->addWidget(new QLabel(text, pair));
        layout->addWidget(field, 1);
        if (extra)
            layout->addWidget(extra);
        pair->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
        return pair;
    };
    row->addWidget(labelled(tr("ID"), m_idEdit, m_directionBox));
    row->addWidget(labelled(tr("Object"), m_objectEdit));
    row->addWidget(labelled(tr("Data"), m_dataEdit));
    row->addWidget(m_textEdit);
    for (QLineEdit *edit : { m_idEdit, m_objectEdit, m_dataEdit, m_textEdit })
        connect(edit, &QLineEdit::textChanged, this, &CanMonitor::applyFilter);
    connect(m_directionBox, &QComboBox::currentIndexChanged, this, &CanMonitor::applyFilter);
    return bar;
}

void CanMonitor::setupView()
{
    m_view->setObjectName(QStringLiteral("frames"));
    m_view->setModel(m_filter);
    // The table is repainted with every batch of frames: each row's texts are laid out once.
    m_view->setItemDelegate(new StaticTextDelegate(m_view));
    QuietScrollBar::install(m_view);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setAlternatingRowColors(true);
    m_view->setShowGrid(false);
    m_view->setWordWrap(false);
    m_view->setHorizontalScrollMode(QAbstractItemView::ScrollPerPixel);
    QHeaderView *rows = m_view->verticalHeader();
    rows->hide();
    rows->setSectionResizeMode(QHeaderView::Fixed); // no per-row measuring with 100,000 rows
    rows->setDefaultSectionSize(QFontMetrics(style::monospaceFont()).height() + 4);
    QHeaderView *columns = m_view->horizontalHeader();
    columns->setHighlightSections(false);
    columns->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    columns->setStretchLastSection(true);
    const QFontMetrics mono(style::monospaceFont());
    const QFontMetrics prop(font());
    const auto width = [](const QFontMetrics &fm, const char *sample) {
        return fm.horizontalAdvance(QString::fromLatin1(sample)) + 16;
    };
    columns->resizeSection(CanMonitorModel::Time, width(mono, "00000.000000"));
    columns->resizeSection(CanMonitorModel::Direction, width(prop, "Dir."));
    columns->resizeSection(CanMonitorModel::Id, width(mono, "1FFFFFFF"));
    columns->resizeSection(CanMonitorModel::Length, width(prop, "Len"));
    columns->resizeSection(CanMonitorModel::Data, width(mono, "00 00 00 00 00 00 00 00"));
    columns->resizeSection(CanMonitorModel::Service, width(prop, "Heartbeat"));
    columns->resizeSection(CanMonitorModel::Node, width(prop, "Node"));
}

void CanMonitor::setConnection(DeviceConnection *connection)
{
    const canopen::NetworkNode at = canopen::networkNodeOf(connection);
    setBus(at ? at.network->bus() : nullptr);
    disconnect(m_dictionaryWatch);
    if (!at)
        return;
    // Every node the network has a description of (the connected one, once it has chosen its
    // description; the displays an NM17x line identified), now and as they come: their PDOs
    // are shown field by field with names and units.
    canopen::CanNetwork *network = at.network;
    for (const canopen::NodeId node : network->describedNodes())
        m_model->decoder().setDictionary(node, *network->dictionary(node));
    if (!network->dictionary(at.node))
        m_model->decoder().setDictionary(at.node, connection->dictionary());
    m_dictionaryWatch = connect(network, &canopen::CanNetwork::dictionaryChanged, this,
                                [this, network](canopen::NodeId node) {
                                    if (const ObjectDictionary *d = network->dictionary(node))
                                        m_model->decoder().setDictionary(node, *d);
                                });
}

void CanMonitor::setBus(CanBus *bus)
{
    if (bus == m_model->bus())
        return;
    m_model->setBus(bus);
    m_sender->setBus(bus);
    updateStatus();
}

bool CanMonitor::autoscroll() const
{
    return m_autoscroll->isChecked();
}

void CanMonitor::setAutoscroll(bool on)
{
    m_autoscroll->setChecked(on);
}

void CanMonitor::setPaused(bool paused)
{
    if (m_pauseButton->isChecked() != paused)
        m_pauseButton->setChecked(paused); // comes back here through toggled
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
    m_model->setPaused(paused);
    updateStatus();
}

void CanMonitor::clear()
{
    m_model->clear();
}

void CanMonitor::applyFilter()
{
    CanFrameFilter f;
    const auto ids = CanFrameFilter::parseIds(m_idEdit->text());
    markInvalid(m_idEdit, ids ? QString() : ids.error().message(),
                tr("COB-IDs in hex: single ids and ranges, comma separated"));
    const auto object = f.setObject(m_objectEdit->text());
    markInvalid(m_objectEdit, object ? QString() : object.error().message(),
                tr("Object index (hex), optionally :sub-index"));
    const auto data = f.setDataPattern(m_dataEdit->text());
    markInvalid(m_dataEdit, data ? QString() : data.error().message(),
                tr("Data from byte 0 in hex; ?? matches any byte, ? any digit"));
    if (!ids || !object || !data)
        return; // keep the last valid filter while the user types
    f.ids = ids.value();
    f.direction = CanFrameFilter::Direction(m_directionBox->currentData().toInt());
    f.text = m_textEdit->text().trimmed();
    m_filter->setCriteria(f);
    updateStatus();
}

void CanMonitor::onFlushed()
{
    if (autoscroll() && isVisible())
        m_view->scrollToBottom();
    updateStatus();
}

void CanMonitor::updateStatus()
{
    QString text = tr("%1 frames").arg(m_model->rowCount());
    if (m_filter->rowCount() != m_model->rowCount())
        text += tr(", %1 shown").arg(m_filter->rowCount());
    if (m_model->droppedCount() > 0)
        text += tr(", %1 oldest dropped").arg(m_model->droppedCount());
    if (isPaused())
        text += tr(" — paused, %1 waiting").arg(m_model->pendingCount());
    if (!bus())
        text += tr(" — no CAN bus");
    style::setFrequentText(m_status, text); // changes with every batch of frames
}

Result<void> CanMonitor::saveLog(const QString &path, const QString &interface) const
{
    const QString iface =
        !interface.isEmpty() ? interface : candump::interfaceName(bus() ? bus()->name() : QString());
    db::files::removeStaleTemporaries(path); // what a killed writer left
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return Error(Error::Kind::Io, tr("Cannot write %1: %2").arg(path, file.errorString()));
    for (int row = 0; row < m_filter->rowCount(); ++row) {
        const int source = m_filter->mapToSource(m_filter->index(row, 0)).row();
        const CanMonitorModel::Entry &e = m_model->entry(source);
        if (e.frame.frameType() == QCanBusFrame::ErrorFrame)
            continue; // no classic-frame form in the log
        file.write(candump::formatLine(e.epochUs, iface, e.frame).toLatin1() + '\n');
    }
    if (!file.commit())
        return Error(Error::Kind::Io, tr("Cannot write %1: %2").arg(path, file.errorString()));
    return {};
}

void CanMonitor::saveLogAs()
{
    const QString suggested =
        QStringLiteral("candump-%1.log")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyy-MM-dd_hhmmss")));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save CAN log"), suggested,
                                                      tr("candump logs (*.log);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const auto saved = saveLog(path); !saved)
        QMessageBox::warning(this, tr("Save CAN log"), saved.error().message());
}

} // namespace db::widgets
