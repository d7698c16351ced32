#include "paramcompareview.h"
#include "core/filewriter.h"

#include "core/printable.h"
#include "paramcomparemodel.h"
#include "paramcomparepdf.h"
#include "paramcomparereport.h"
#include "widgets/common/flowlayout.h"
#include "widgets/common/recentfolder.h"
#include "widgets/common/widgetstyle.h"

#include <QCheckBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSaveFile>
#include <QTableView>
#include <QVBoxLayout>

namespace db::widgets {

ParamCompareView::ParamCompareView(QWidget *parent)
    : QWidget(parent)
    , m_model(new ParamCompareModel(this))
    , m_filter(new ParamCompareFilter(this))
    , m_fileLabel(new QLabel(this))
    , m_counts(new QLabel(this))
    , m_onlyDiff(new QCheckBox(tr("Only &differences"), this))
    , m_withDefaults(new QCheckBox(tr("Status includes d&efaults"), this))
    , m_hex(new QCheckBox(tr("He&x"), this))
    , m_table(new QTableView(this))
    , m_progress(new QProgressBar(this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
    , m_load(new QPushButton(tr("&Load Set…"), this))
    , m_reread(new QPushButton(tr("Re-read &Device"), this))
    , m_selectDiff(new QPushButton(tr("Select Differences"), this))
    , m_selectNone(new QPushButton(tr("Select None"), this))
    , m_store(new QCheckBox(tr("Store permanently afterwards (1010h)"), this))
    , m_restoreButton(new QPushButton(tr("&Restore Selected…"), this))
    , m_status(new QLabel(this))
{
    m_counts->setObjectName(QStringLiteral("counts"));
    m_onlyDiff->setObjectName(QStringLiteral("onlyDifferences"));
    m_withDefaults->setObjectName(QStringLiteral("withDefaults"));
    m_store->setObjectName(QStringLiteral("storeAfterRestore"));
    m_restoreButton->setObjectName(QStringLiteral("restoreSelected"));
    m_status->setObjectName(QStringLiteral("status"));
    m_fileLabel->setObjectName(QStringLiteral("fileLabel"));

    m_filter->setSourceModel(m_model);
    m_table->setModel(m_filter);
    m_table->setAlternatingRowColors(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    m_table->setWordWrap(false);
    QHeaderView *h = m_table->horizontalHeader();
    const int ch = QFontMetrics(style::monospaceFont()).horizontalAdvance(QLatin1Char('0'));
    h->resizeSection(ParamCompareModel::Select, 28);
    h->resizeSection(ParamCompareModel::Address, ch * 9 + 20);
    h->resizeSection(ParamCompareModel::Name, 300);
    h->resizeSection(ParamCompareModel::DeviceValue, ch * 24);
    h->resizeSection(ParamCompareModel::FileValue, ch * 24);
    h->resizeSection(ParamCompareModel::DefaultValue, ch * 20);
    h->setSectionResizeMode(ParamCompareModel::Status, QHeaderView::Stretch);

    m_fileLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_fileLabel->setWordWrap(true);
    m_counts->setTextFormat(Qt::RichText);
    m_progress->setMaximumWidth(240);
    m_progress->setFormat(QStringLiteral("%v / %m"));
    m_withDefaults->setToolTip(tr("Off: the status compares device and file only. On: a row "
                                  "also counts as changed or missing when the defaults differ."));
    m_store->setToolTip(tr("After every row was written and verified, write \"save\" to 1010h "
                           "so the values survive a power cycle"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *top = new QHBoxLayout;
    top->addWidget(m_load);
    top->addWidget(m_reread);
    top->addSpacing(8);
    top->addWidget(m_fileLabel, 1);
    auto *second = new FlowLayout; // rows wrap on a narrow window
    second->addWidget(m_counts);
    second->addWidget(m_onlyDiff);
    second->addWidget(m_withDefaults);
    second->addWidget(m_hex);
    // The comparison as a CSV file (for the commissioning record).
    auto *saveReport = new QPushButton(tr("Save &Report…"), this);
    saveReport->setObjectName(QStringLiteral("saveReport"));
    saveReport->setToolTip(tr("Save the comparison as a PDF report (identity, date, files and "
                              "the differences) or every row as a CSV file"));
    connect(saveReport, &QPushButton::clicked, this, [this] {
        const QString pdf = tr("PDF report (*.pdf)");
        QString filter = pdf;
        QString path = QFileDialog::getSaveFileName(
            this, tr("Save Comparison Report"),
            QDir(recentFolder(QStringLiteral("csv"))).filePath(QStringLiteral("comparison.pdf")),
            pdf + QStringLiteral(";;") + tr("CSV (*.csv)"), &filter);
        rememberFolder(QStringLiteral("csv"), path);
        if (path.isEmpty())
            return;
        const bool asPdf = QFileInfo(path).suffix().isEmpty()
            ? filter == pdf
            : QFileInfo(path).suffix().compare(QLatin1String("pdf"), Qt::CaseInsensitive) == 0;
        if (QFileInfo(path).suffix().isEmpty())
            path += asPdf ? QStringLiteral(".pdf") : QStringLiteral(".csv");
        const auto saved = asPdf ? saveReportPdf(path) : saveReportCsv(path);
        showStatus(saved ? tr("Saved the comparison to %1").arg(QDir::toNativeSeparators(path))
                         : saved.error().message(),
                   saved ? QColor() : style::errorColor());
    });
    auto *withFile = new QPushButton(tr("Compare with &File…"), this);
    withFile->setObjectName(QStringLiteral("compareWithFile"));
    withFile->setToolTip(tr("Compare the loaded set with another file instead of the device"));
    connect(withFile, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Compare with Parameter Set"), recentFolder(QStringLiteral("dbp")),
            tr("Parameter sets (*.dbp *.txt);;All files (*)"));
        rememberFolder(QStringLiteral("dbp"), path);
        if (!path.isEmpty())
            loadReferenceFile(path);
    });
    top->insertWidget(2, withFile);
    auto *bottom = new FlowLayout;
    bottom->addWidget(saveReport);
    bottom->addWidget(m_selectDiff);
    bottom->addWidget(m_selectNone);
    bottom->addWidget(m_progress);
    bottom->addWidget(m_cancel);
    bottom->addWidget(m_store);
    bottom->addWidget(m_restoreButton);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addLayout(second);
    layout->addWidget(m_table, 1);
    layout->addLayout(bottom);
    layout->addWidget(m_status);

    connect(m_load, &QPushButton::clicked, this, &ParamCompareView::chooseFile);
    connect(m_reread, &QPushButton::clicked, this, &ParamCompareView::refreshDevice);
    connect(m_selectDiff, &QPushButton::clicked, m_model, &ParamCompareModel::selectDifferences);
    connect(m_selectNone, &QPushButton::clicked, m_model, &ParamCompareModel::selectNone);
    connect(m_restoreButton, &QPushButton::clicked, this, &ParamCompareView::restoreSelected);
    connect(m_cancel, &QPushButton::clicked, this, &ParamCompareView::cancel);
    connect(m_onlyDiff, &QCheckBox::toggled, m_filter, &ParamCompareFilter::setOnlyDifferences);
    m_onlyDiff->setChecked(true); // what a comparison is for; the full list is one click away
    connect(m_withDefaults, &QCheckBox::toggled, this, &ParamCompareView::compare);
    connect(m_hex, &QCheckBox::toggled, m_model, &ParamCompareModel::setHex);
    connect(m_model, &ParamCompareModel::selectionChanged, this, &ParamCompareView::updateActions);
    setIdle();
    m_fileLabel->setText(tr("No parameter set loaded. <i>Load Set…</i> reads a file made by "
                            "<i>Back Up…</i> or <code>drivebench-cli backup</code>; nothing is "
                            "written to the device until you restore."));
}

ParamCompareView::~ParamCompareView()
{
    disconnect(m_stateConnection);
    // Runners stop without signalling into a half-destroyed page.
    if (m_backup)
        disconnect(m_backup.get(), nullptr, this, nullptr);
    if (m_restore)
        disconnect(m_restore.get(), nullptr, this, nullptr);
}

void ParamCompareView::setConnection(DeviceConnection *connection)
{
    if (connection == m_connection)
        return;
    cancel();
    disconnect(m_stateConnection);
    m_connection = connection;
    if (m_referenceFile.isEmpty())
        m_device.reset();
    if (connection) {
        m_stateConnection = connect(connection, &DeviceConnection::stateChanged, this,
                                    [this](DeviceConnection::State state) {
                                        if (state == DeviceConnection::State::Connected && m_file
                                            && !isBusy() && m_referenceFile.isEmpty())
                                            refreshDevice();
                                        updateActions();
                                    });
    }
    compare();
    if (m_file && connection && connection->isConnected() && m_referenceFile.isEmpty())
        refreshDevice();
}

Result<void> ParamCompareView::loadReferenceFile(const QString &path)
{
    if (!m_file)
        return Error(Error::Kind::InvalidArgument, tr("Load a parameter set first"));
    auto set = ParameterSet::load(path);
    if (!set) {
        const Error &e = set.error();
        showStatus(e.kind() == Error::Kind::Malformed
                       ? e.message()
                       : tr("Cannot load %1: %2").arg(QFileInfo(path).fileName(), e.message()),
                   style::errorColor());
        return e;
    }
    cancel();
    m_referenceFile = QFileInfo(path).fileName();
    m_device = set.value();
    compare();
    showStatus(tr("Compared %1 with %2. Nothing has been written; Re-read Device compares with "
                  "the device again.")
                   .arg(m_fileOrigin, m_referenceFile));
    return {};
}

void ParamCompareView::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Load Parameter Set"), recentFolder(QStringLiteral("dbp")),
        tr("Parameter sets (*.dbp *.txt);;All files (*)"));
    rememberFolder(QStringLiteral("dbp"), path);
    if (!path.isEmpty())
        loadFile(path);
}

Result<void> ParamCompareView::loadFile(const QString &path)
{
    auto set = ParameterSet::load(path);
    if (!set) {
        // A parse error names the file and line itself ("set.dbp:19: ..."); others get the name.
        const Error &e = set.error();
        showStatus(e.kind() == Error::Kind::Malformed
                       ? e.message()
                       : tr("Cannot load %1: %2").arg(QFileInfo(path).fileName(), e.message()),
                   style::errorColor());
        return set.error();
    }
    setFileSet(set.value(), QFileInfo(path).fileName());
    return {};
}

void ParamCompareView::setFileSet(const ParameterSet &set, const QString &origin)
{
    m_file = set;
    m_fileOrigin = origin;
    const DeviceIdentity &id = set.identity;
    m_fileLabel->setText(
        tr("<b>%1</b> — %2 %3, %n object(s), saved %4 from %5", nullptr, set.size())
            .arg(origin.toHtmlEscaped(), id.vendorName.toHtmlEscaped(),
                 id.productName.toHtmlEscaped(),
                 set.created.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm")),
                 set.source.toHtmlEscaped()));
    showStatus(tr("Loaded %1. Nothing has been written to the device.").arg(origin));
    compare();
    if (m_referenceFile.isEmpty())
        refreshDevice();
}

Result<void> ParamCompareView::saveReportCsv(const QString &path) const
{
    const ParameterComparison &c = m_model->comparison();
    if (c.rows.isEmpty())
        return Error(Error::Kind::InvalidArgument, tr("Nothing compared yet: no report saved"));
    const auto field = [](QString text) {
        if (text.contains(QLatin1Char(',')) || text.contains(QLatin1Char('"'))
            || text.contains(QLatin1Char('\n'))) {
            text.replace(QLatin1String("\""), QLatin1String("\"\""));
            text = QLatin1Char('"') + text + QLatin1Char('"');
        }
        return text;
    };
    QStringList lines;
    QStringList header { tr("Address"), tr("Name") };
    for (const QString &side : c.sideNames)
        header << side;
    header << tr("Unit") << tr("Status");
    lines << header.join(QLatin1Char(','));
    for (const CompareRow &row : c.rows) {
        QStringList cells { c.addressFormat->format(row.address), field(printable(row.name)) };
        for (int side = 0; side < c.sideNames.size(); ++side)
            cells << field(row.valueText(side));
        cells << field(row.unit) << compareStatusName(row.status);
        lines << cells.join(QLatin1Char(','));
    }
    db::files::removeStaleTemporaries(path); // what a killed writer left
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)
        || file.write((lines.join(QLatin1Char('\n')) + QLatin1Char('\n')).toUtf8()) < 0
        || !file.commit())
        return Error(Error::Kind::Io,
                     tr("Report not saved to %1: %2")
                         .arg(QDir::toNativeSeparators(path), file.errorString()));
    return {};
}

Result<void> ParamCompareView::saveReportPdf(const QString &path) const
{
    const ParameterComparison &c = m_model->comparison();
    if (c.rows.isEmpty())
        return Error(Error::Kind::InvalidArgument, tr("Nothing compared yet: no report saved"));
    ComparisonReportInfo info;
    info.created = QDateTime::currentDateTime();
    info.fileOrigin = m_fileOrigin;
    info.referenceFile = m_referenceFile;
    info.note = m_otherUnit;
    const auto hex = [](quint32 v) {
        return QStringLiteral("%1").arg(v, 8, 16, QLatin1Char('0')).toUpper() + QLatin1Char('h');
    };
    const auto named = [](const QString &name, const QString &number) {
        return name.isEmpty()  ? number
            : number.isEmpty() ? name
                               : QStringLiteral("%1 (%2)").arg(name, number);
    };
    if (m_device) {
        const ParameterSet &d = *m_device;
        // The numbers the device reported (read for the identity check), else the set's own.
        const auto reported = [&d](ObjectAddress a) -> std::optional<quint32> {
            const ParameterEntry *e = d.find(a);
            return e ? std::optional<quint32>(quint32(e->raw.toULongLong())) : std::nullopt;
        };
        const auto vendor = reported({ 0x1018, 1 });
        const auto product = reported({ 0x1018, 2 });
        const auto serial = reported({ 0x1018, 4 });
        info.vendor = named(d.identity.vendorName,
                            vendor                                       ? hex(*vendor)
                                : d.vendorIdKnown && d.identity.vendorId ? hex(d.identity.vendorId)
                                                                         : QString());
        info.product =
            named(d.identity.productName,
                  product                                            ? hex(*product)
                      : d.productCodeKnown && d.identity.productCode ? hex(d.identity.productCode)
                                                                     : QString());
        info.revision = d.identity.revision;
        info.serialNumber = serial ? ParameterSet::identityNumber(*serial) : d.serialNumber;
    }
    if (m_referenceFile.isEmpty() && m_connection)
        info.device = m_connection->uri().toString();
    return saveComparisonPdf(path, info, c);
}

QString ParamCompareView::countsText() const
{
    return m_model->comparison().countsText();
}

QString ParamCompareView::statusText() const
{
    return m_status->text();
}

bool ParamCompareView::isBusy() const
{
    return (m_backup && m_backup->isRunning()) || (m_restore && m_restore->isRunning());
}

void ParamCompareView::setCompareWithDefaults(bool on)
{
    m_withDefaults->setChecked(on);
}

void ParamCompareView::setOnlyDifferences(bool on)
{
    m_onlyDiff->setChecked(on);
}

void ParamCompareView::setStoreAfterRestore(bool on)
{
    m_store->setChecked(on);
}

void ParamCompareView::restoreSelected()
{
    const QList<ObjectAddress> rows = m_model->selection();
    if (rows.isEmpty() || !m_connection)
        return;
    QStringList names;
    for (ObjectAddress a : rows.mid(0, 12)) {
        const ObjectDef *def = m_connection->dictionary().find(a);
        names.append(
            QStringLiteral("%1  %2").arg(a.toString(), def ? def->displayName() : QString()));
    }
    if (rows.size() > names.size())
        names.append(tr("… and %n more", nullptr, int(rows.size() - names.size())));
    QMessageBox box(QMessageBox::Question, tr("Restore Parameters"),
                    tr("Write %n selected value(s) from %1 to %2?", nullptr, int(rows.size()))
                        .arg(m_fileOrigin, m_connection->uri().toString()),
                    QMessageBox::Cancel, this);
    const QString store = m_store->isChecked()
        ? tr("Afterwards the values are stored permanently (1010h).")
        : tr("The values are not stored permanently; they are lost at the next power cycle "
             "unless you store them.");
    box.setInformativeText(m_otherUnit.isEmpty() ? store
                                                 : m_otherUnit + QStringLiteral("\n\n") + store);
    if (!m_otherUnit.isEmpty())
        box.setIcon(QMessageBox::Warning);
    box.setDetailedText(names.join(QLatin1Char('\n')));
    QPushButton *go = box.addButton(tr("Restore"), QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    if (box.clickedButton() == go)
        startRestore();
}

bool ParamCompareView::askOtherUnit(const QString &question)
{
    QMessageBox box(QMessageBox::Warning, tr("Another Unit"), question, QMessageBox::Cancel, this);
    QPushButton *go = box.addButton(tr("Compare Anyway"), QMessageBox::AcceptRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    return box.clickedButton() == go;
}

void ParamCompareView::showStatus(const QString &text, const QColor &color)
{
    m_status->setText(text);
    style::setTextColor(m_status, color);
}

} // namespace db::widgets
