// ScopePage: construction of the controls and their state.
#include "scopepage.h"

#include "scope/pollingsource.h"
#include "scope/recorder.h"
#include "scopechannelmodel.h"
#include "scopecursors.h"
#include "scopemeasurements.h"
#include "scopeplot.h"
#include "widgets/common/widgetstyle.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenu>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QTableView>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace db::widgets {

namespace {

QDoubleSpinBox *secondsBox(QWidget *parent, double value, double max)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setRange(0.0, max);
    box->setDecimals(3);
    box->setSingleStep(0.1);
    box->setSuffix(QStringLiteral(" s"));
    box->setValue(value);
    return box;
}

QDoubleSpinBox *levelBox(QWidget *parent)
{
    auto *box = new QDoubleSpinBox(parent);
    box->setRange(-1e12, 1e12);
    box->setDecimals(3);
    box->setAccelerated(true);
    return box;
}

} // namespace

ScopePage::ScopePage(QWidget *parent)
    : QWidget(parent)
    , m_recorder(new scope::Recorder(this))
    , m_plot(new ScopePlot(this))
    , m_model(new ScopeChannelModel(m_recorder, m_plot, this))
    , m_measurements(new ScopeMeasurements(this))
{
    setObjectName(QStringLiteral("scopePage"));
    setAcceptDrops(true);
    m_plot->setRecorder(m_recorder);

    // The controls scroll vertically, so that the page fits a laptop screen with the docks.
    auto *leftScroll = new QScrollArea(this);
    leftScroll->setWidgetResizable(true);
    leftScroll->setFrameShape(QFrame::NoFrame);
    leftScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    leftScroll->setMinimumWidth(270); // channel names stay readable next to the plot
    auto *left = new QWidget(leftScroll);
    leftScroll->setWidget(left);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 4, 0);
    leftLayout->addWidget(createChannelPanel(), 1);
    leftLayout->addWidget(createAcquisitionPanel());

    auto *right = new QWidget(this);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(4, 0, 0, 0);
    rightLayout->setSpacing(2);
    rightLayout->addWidget(createToolBar());
    auto *vertical = new QSplitter(Qt::Vertical, right);
    vertical->addWidget(m_plot);
    vertical->addWidget(m_measurements);
    vertical->setStretchFactor(0, 4);
    vertical->setStretchFactor(1, 1);
    vertical->setChildrenCollapsible(false);
    rightLayout->addWidget(vertical, 1);

    auto *split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(leftScroll);
    split->addWidget(right);
    split->setStretchFactor(1, 1);
    split->setSizes({ 360, 900 });
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(split);

    connect(m_recorder, &scope::Recorder::stateChanged, this, [this] {
        updateControls();
        updateStatus();
    });
    connect(m_recorder, &scope::Recorder::channelsChanged, this, [this] {
        updateTriggerChannels();
        updateControls();
        scheduleMeasurements();
    });
    connect(m_recorder, &scope::Recorder::captureCompleted, this, &ScopePage::scheduleMeasurements);
    connect(m_recorder, &scope::Recorder::errorOccurred, this,
            [this](const Error &e) { showMessage(e.message(), true); });
    connect(m_plot->cursors(), &ScopeCursors::moved, this, &ScopePage::scheduleMeasurements);
    connect(m_plot, &ScopePlot::channelStyleChanged, this, &ScopePage::scheduleMeasurements);

    m_statusTimer.setInterval(1000 / kStatusHz);
    connect(&m_statusTimer, &QTimer::timeout, this, [this] {
        updateStatus();
        m_model->refreshCounts();
        if (m_recorder->isRunning())
            scheduleMeasurements();
    });
    m_statusTimer.start();
    m_measureTimer.setSingleShot(true);
    m_measureTimer.setInterval(kMeasureDelayMs);
    connect(&m_measureTimer, &QTimer::timeout, this, &ScopePage::measure);

    updateTriggerChannels();
    updateControls();
    updateStatus();
    showMessage(tr("Add channels by address, or drag objects here from the object dictionary."),
                false);
}

ScopePage::~ScopePage()
{
    m_plot->setRecorder(nullptr);
    m_recorder->stop();
}

QWidget *ScopePage::createChannelPanel()
{
    auto *box = new QGroupBox(tr("Channels"), this);
    auto *layout = new QVBoxLayout(box);
    m_channelView = new QTableView(box);
    m_channelView->setObjectName(QStringLiteral("scopeChannels"));
    m_channelView->setModel(createTableModel()); // m_model, with the PDO of PDO channels
    m_channelView->verticalHeader()->setVisible(false);
    m_channelView->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    m_channelView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_channelView->setSelectionMode(QAbstractItemView::SingleSelection);
    m_channelView->setEditTriggers(QAbstractItemView::DoubleClicked
                                   | QAbstractItemView::EditKeyPressed);
    m_channelView->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_channelView->horizontalHeader()->setSectionResizeMode(ScopeChannelModel::Name,
                                                            QHeaderView::Stretch);
    m_channelView->setWordWrap(false);
    connect(m_channelView, &QTableView::doubleClicked, this, [this](const QModelIndex &index) {
        if (index.column() == ScopeChannelModel::Name)
            chooseColor(index.row());
    });
    layout->addWidget(m_channelView, 1);

    m_addressEdit = new QLineEdit(box);
    m_addressEdit->setObjectName(QStringLiteral("scopeAddress"));
    m_addressEdit->setPlaceholderText(tr("Object address, e.g. 6064:0, 6078:0"));
    m_addressEdit->setToolTip(tr("Object addresses INDEX:SUB (hex), separated by commas"));
    m_rateBox = new QSpinBox(box);
    m_rateBox->setRange(0, 60000);
    m_rateBox->setValue(0);
    m_rateBox->setSuffix(tr(" ms"));
    m_rateBox->setSpecialValueText(tr("max rate"));
    m_rateBox->setToolTip(tr("Polling period of new channels (max rate: as fast as the link "
                             "allows)"));
    m_addButton = new QPushButton(tr("Add"), box);
    m_removeButton = new QPushButton(tr("Remove"), box);
    auto *addRow = new QHBoxLayout;
    addRow->addWidget(m_addressEdit, 1);
    addRow->addWidget(m_addButton);
    layout->addLayout(addRow);
    auto *rateRow = new QHBoxLayout;
    rateRow->addWidget(new QLabel(tr("Rate"), box));
    rateRow->addWidget(m_rateBox);
    rateRow->addStretch(1);
    rateRow->addWidget(m_removeButton);
    layout->addLayout(rateRow);
    layout->addWidget(createSourceRow(box));
    connect(m_addButton, &QPushButton::clicked, this, &ScopePage::addFromEdit);
    connect(m_addressEdit, &QLineEdit::returnPressed, this, &ScopePage::addFromEdit);
    connect(m_removeButton, &QPushButton::clicked, this, &ScopePage::removeSelected);
    return box;
}

QWidget *ScopePage::createAcquisitionPanel()
{
    auto *box = new QGroupBox(tr("Acquisition"), this);
    auto *form = new QFormLayout(box);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_modeBox = new QComboBox(box);
    m_modeBox->addItems({ tr("Run (until Stop)"), tr("Single (one trigger)"), tr("Normal (re-arm)"),
                          tr("Roll (last seconds)") });
    m_rollBox = secondsBox(box, 10.0, 3600.0);
    m_triggerChannelBox = new QComboBox(box);
    m_triggerChannelBox->setObjectName(QStringLiteral("scopeTriggerChannel"));
    connect(m_triggerChannelBox, &QComboBox::activated, this,
            [this] { m_triggerChoice = m_triggerChannelBox->currentData().toString(); });
    m_triggerKindBox = new QComboBox(box);
    m_triggerKindBox->addItems({ tr("rising edge"), tr("falling edge"), tr("above level"),
                                 tr("below level"), tr("inside window"), tr("outside window"),
                                 tr("bit set"), tr("bit clear") });
    m_levelBox = levelBox(box);
    m_level2Box = levelBox(box);
    m_bitBox = new QSpinBox(box);
    m_bitBox->setRange(0, 63);
    m_preBox = secondsBox(box, 0.1, 3600.0);
    m_postBox = secondsBox(box, 1.0, 3600.0);
    form->addRow(tr("Mode"), m_modeBox);
    form->addRow(tr("Roll window"), m_rollBox);
    form->addRow(tr("Trigger on"), m_triggerChannelBox);
    form->addRow(tr("Condition"), m_triggerKindBox);
    form->addRow(tr("Level"), m_levelBox);
    form->addRow(tr("Level 2"), m_level2Box);
    form->addRow(tr("Bit"), m_bitBox);
    form->addRow(tr("Pre-trigger"), m_preBox);
    form->addRow(tr("Post-trigger"), m_postBox);
    for (QWidget *w : std::initializer_list<QWidget *> { m_modeBox, m_triggerKindBox })
        connect(qobject_cast<QComboBox *>(w), &QComboBox::currentIndexChanged, this,
                &ScopePage::updateControls);

    auto *buttons = new QHBoxLayout;
    m_startButton = new QPushButton(tr("Start"), box);
    m_startButton->setObjectName(QStringLiteral("scopeStart"));
    m_stopButton = new QPushButton(tr("Stop"), box);
    m_stopButton->setObjectName(QStringLiteral("scopeStop"));
    buttons->addWidget(m_startButton);
    buttons->addWidget(m_stopButton);
    form->addRow(buttons);
    connect(m_startButton, &QPushButton::clicked, this, &ScopePage::start);
    connect(m_stopButton, &QPushButton::clicked, this, &ScopePage::stop);

    m_stateLabel = new QLabel(box);
    m_stateLabel->setObjectName(QStringLiteral("scopeState"));
    m_countLabel = new QLabel(box);
    m_countLabel->setObjectName(QStringLiteral("scopeCounts"));
    m_messageLabel = new QLabel(box);
    m_messageLabel->setObjectName(QStringLiteral("scopeMessage"));
    m_messageLabel->setWordWrap(true);
    form->addRow(tr("State"), m_stateLabel);
    form->addRow(tr("Samples"), m_countLabel);
    form->addRow(m_messageLabel);
    return box;
}

QWidget *ScopePage::createToolBar()
{
    auto *bar = new QToolBar(this);
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addAction(tr("Autoscale"), m_plot, &ScopePlot::autoscale)
        ->setToolTip(tr("Fit time and values to the data (key A)"));
    m_cursorAction = bar->addAction(tr("Cursors"));
    m_cursorAction->setCheckable(true);
    m_cursorAction->setToolTip(tr("A/B cursors: drag the lines to measure"));
    connect(m_cursorAction, &QAction::toggled, this, &ScopePage::setCursorsEnabled);
    bar->addAction(tr("Analyse…"), this, &ScopePage::showAnalysis)
        ->setToolTip(tr("Spectrum and step response of the selected channel between the cursors "
                        "(or in view)"));
    bar->addSeparator();
    bar->addAction(tr("Open…"), this, [this] { promptOpen(); });
    auto *csvMenu = new QMenu(bar);
    csvMenu->addAction(tr("Whole recording…"), this, [this] { promptExportCsv(false); });
    csvMenu->addAction(tr("Visible range…"), this, [this] { promptExportCsv(true); });
    QAction *csv = bar->addAction(tr("Export CSV"));
    csv->setMenu(csvMenu);
    if (auto *button = qobject_cast<QToolButton *>(bar->widgetForAction(csv)))
        button->setPopupMode(QToolButton::InstantPopup);
    bar->addAction(tr("Export image…"), this, [this] { promptExportImage(); });
    return bar;
}

void ScopePage::updateControls()
{
    const bool running = m_recorder->isRunning();
    const auto mode = scope::Recorder::Mode(m_modeBox->currentIndex());
    const bool triggered =
        mode == scope::Recorder::Mode::Single || mode == scope::Recorder::Mode::Normal;
    const int kind = m_triggerKindBox->currentIndex();
    const bool window = kind == int(scope::Trigger::Kind::WindowInside)
        || kind == int(scope::Trigger::Kind::WindowOutside);
    const bool bit =
        kind == int(scope::Trigger::Kind::BitSet) || kind == int(scope::Trigger::Kind::BitClear);
    m_modeBox->setEnabled(!running);
    m_rollBox->setEnabled(!running && mode == scope::Recorder::Mode::Roll);
    for (QWidget *w : std::initializer_list<QWidget *> { m_triggerChannelBox, m_triggerKindBox,
                                                         m_preBox, m_postBox })
        w->setEnabled(!running && triggered);
    m_levelBox->setEnabled(!running && triggered && !bit);
    m_level2Box->setEnabled(!running && triggered && window);
    m_bitBox->setEnabled(!running && triggered && bit);
    m_startButton->setEnabled(!running);
    m_stopButton->setEnabled(running);
    m_addButton->setEnabled(!running);
    m_removeButton->setEnabled(!running && m_recorder->channelCount() > 0);
    m_addressEdit->setEnabled(!running);
    const bool canopen = m_connection && m_connection->protocolKey() == u"canopen";
    m_sourceLabel->setVisible(canopen);
    m_sourceBox->setVisible(canopen);
    m_sourceBox->setEnabled(!running);
    m_mapButton->setVisible(canopen);
    m_mapButton->setEnabled(!running && !m_unmapped.isEmpty() && !m_pdoRequest);
}

void ScopePage::updateStatus()
{
    using State = scope::Recorder::State;
    static const QHash<State, QString> names = {
        { State::Idle, tr("idle") },
        { State::Recording, tr("recording") },
        { State::Armed, tr("armed, waiting for the trigger") },
        { State::Triggered, tr("triggered") },
        { State::Stopped, tr("stopped") },
    };
    const State state = m_recorder->state();
    m_stateLabel->setText(names.value(state));
    style::setTextColor(m_stateLabel,
                        state == State::Recording || state == State::Triggered ? style::okColor()
                            : state == State::Armed ? style::warningColor()
                                                    : QColor());
    qint64 samples = 0;
    qint64 lost = 0;
    for (int i = 0; i < m_recorder->channelCount(); ++i) {
        samples += m_recorder->buffer(i).size();
        lost += m_recorder->buffer(i).dropped();
    }
    m_countLabel->setText(
        tr("%1, %2 lost").arg(QLocale().toString(samples), QLocale().toString(lost)));
    style::setTextColor(m_countLabel, lost > 0 ? style::warningColor() : QColor());
}

void ScopePage::updateTriggerChannels()
{
    // The channel the user chose last (also after it was removed and added again), else the
    // one shown, else the recorder's, else the first.
    const QString current = m_triggerChannelBox->currentData().toString();
    m_triggerChannelBox->clear();
    for (int i = 0; i < m_recorder->channelCount(); ++i) {
        const scope::ChannelInfo &info = m_recorder->channelInfo(i);
        m_triggerChannelBox->addItem(scopeChannelName(*m_recorder, i),
                                     ScopeChannelModel::key(info));
    }
    int pick = m_triggerChoice.isEmpty() ? -1 : m_triggerChannelBox->findData(m_triggerChoice);
    if (pick < 0)
        pick = m_triggerChannelBox->findData(current);
    const int fromRecorder = m_recorder->trigger().channel;
    if (pick < 0 && fromRecorder >= 0 && fromRecorder < m_recorder->channelCount())
        pick = fromRecorder;
    if (pick < 0 && m_triggerChannelBox->count() > 0)
        pick = 0;
    m_triggerChannelBox->setCurrentIndex(pick);
}

void ScopePage::showMessage(const QString &text, bool error)
{
    m_messageLabel->setText(text);
    style::setTextColor(m_messageLabel, error ? style::errorColor() : style::inactiveColor());
}

QString ScopePage::statusText() const
{
    return m_messageLabel->text();
}

} // namespace db::widgets
