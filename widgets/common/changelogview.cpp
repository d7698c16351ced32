#include "changelogview.h"

#include "flowlayout.h"
#include "widgetstyle.h"

#include "core/changelog.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QTableView>
#include <QVBoxLayout>

namespace db::widgets {

ChangeLogModel::ChangeLogModel(ChangeLog *log, QObject *parent)
    : QAbstractTableModel(parent)
    , m_log(log)
{
    connect(log, &ChangeLog::entryAdded, this, [this](int index) {
        beginInsertRows({}, index, index);
        endInsertRows();
    });
    connect(log, &ChangeLog::entryChanged, this, [this](int index) {
        Q_EMIT dataChanged(this->index(index, 0), this->index(index, ColumnCount - 1));
    });
    connect(log, &ChangeLog::entriesRemoved, this, [this] {
        beginResetModel();
        endResetModel();
    });
}

int ChangeLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_log ? 0 : m_log->count();
}

int ChangeLogModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ChangeLogModel::data(const QModelIndex &index, int role) const
{
    if (!m_log || !index.isValid() || index.row() >= m_log->count())
        return {};
    const ChangeLog::Entry &e = m_log->entries().at(index.row());
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case Time:
            return e.time.toString(QStringLiteral("HH:mm:ss.zzz"));
        case Device:
            return e.device;
        case Action:
            return ChangeLog::kindName(e.kind);
        case Object:
            return e.object;
        case OldValue:
            return e.oldValue;
        case NewValue:
            return e.newValue;
        case Result:
            return e.message.isEmpty()
                ? ChangeLog::outcomeName(e.outcome)
                : ChangeLog::outcomeName(e.outcome) + QStringLiteral(": ") + e.message;
        case Stored:
            return ChangeLog::storedText(e);
        }
    }
    if (role == Qt::ToolTipRole) {
        if (index.column() == Stored && e.storable && !e.stored
            && e.outcome == ChangeLog::Outcome::Ok)
            return tr("In the device's working memory only: lost at power-off until the device "
                      "stores its parameters permanently.");
        if (index.column() == Result && !e.message.isEmpty())
            return e.message;
        if (index.column() == Time)
            return e.time.toString(Qt::ISODateWithMs);
    }
    if (role == Qt::ForegroundRole) {
        if (index.column() == Result && e.outcome == ChangeLog::Outcome::Failed)
            return style::errorColor();
        if (index.column() == Stored
            && (e.workingMemoryOnly
                || (e.storable && !e.stored && e.outcome == ChangeLog::Outcome::Ok)))
            return style::warningColor();
    }
    return {};
}

QVariant ChangeLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Time:
        return tr("Time");
    case Device:
        return tr("Device");
    case Action:
        return tr("Action");
    case Object:
        return tr("Object");
    case OldValue:
        return tr("Old value");
    case NewValue:
        return tr("New value");
    case Result:
        return tr("Result");
    case Stored:
        return tr("Stored");
    }
    return {};
}

ChangeLogView::ChangeLogView(ChangeLog *log, QWidget *parent)
    : QWidget(parent)
    , m_log(log)
    , m_model(new ChangeLogModel(log, this))
    , m_table(new QTableView(this))
    , m_summary(new QLabel(this))
{
    m_table->setModel(m_model);
    m_table->setObjectName(QStringLiteral("changeLogTable"));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(false);
    // Widths from the font, not from the contents: measuring a long log would be slow.
    const QFontMetrics fm = m_table->fontMetrics();
    const auto chars = [&fm](int n) {
        return fm.horizontalAdvance(QLatin1Char('m')) * n / 2 + 16;
    };
    const int widths[ChangeLogModel::ColumnCount] = {
        fm.horizontalAdvance(QStringLiteral("00:00:00.000")) + 16,
        fm.horizontalAdvance(ChangeLog::kindName(ChangeLog::Kind::Store)) + 16,
        chars(28),
        chars(12),
        chars(18),
        chars(12),
        chars(8),
        chars(24),
    };
    for (int c = 0; c < ChangeLogModel::ColumnCount; ++c)
        m_table->setColumnWidth(c, widths[c]);
    m_summary->setWordWrap(true);

    auto *save = new QPushButton(tr("Save…"), this);
    save->setObjectName(QStringLiteral("saveChangeLog"));
    save->setToolTip(tr("Save the change log as a CSV file"));
    auto *clear = new QPushButton(tr("Clear"), this);
    clear->setObjectName(QStringLiteral("clearChangeLog"));
    connect(save, &QPushButton::clicked, this, &ChangeLogView::save);
    connect(clear, &QPushButton::clicked, log, &ChangeLog::clear);

    auto *buttons = new FlowLayout;
    buttons->addWidget(save);
    buttons->addWidget(clear);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    layout->addLayout(buttons);

    const auto follow = [this] {
        updateSummary();
        m_table->scrollToBottom();
    };
    connect(log, &ChangeLog::entryAdded, this, follow);
    connect(log, &ChangeLog::entryChanged, this, &ChangeLogView::updateSummary);
    connect(log, &ChangeLog::entriesRemoved, this, &ChangeLogView::updateSummary);
    updateSummary();
}

void ChangeLogView::updateSummary()
{
    int failed = 0;
    int unstored = 0;
    for (const ChangeLog::Entry &e : m_log->entries()) {
        failed += e.outcome == ChangeLog::Outcome::Failed ? 1 : 0;
        unstored += (e.storable && !e.stored && e.outcome == ChangeLog::Outcome::Ok) ? 1 : 0;
    }
    if (m_log->count() == 0) {
        m_summary->setText(tr("Writes, restores, stores, enables, motion and NMT commands of this "
                              "session appear here."));
        return;
    }
    QString text = tr("%n change(s)", nullptr, m_log->count());
    if (failed > 0)
        text += QStringLiteral(", ") + tr("%n failed", nullptr, failed);
    if (unstored > 0)
        text += QStringLiteral(", ") + tr("%n write(s) not stored permanently", nullptr, unstored);
    m_summary->setText(text);
}

QString ChangeLogView::saveTo(const QString &path)
{
    const Error error = m_log->saveCsv(path);
    if (error.isError()) {
        m_summary->setText(error.message());
        return error.message();
    }
    m_summary->setText(tr("Saved to %1").arg(QDir::toNativeSeparators(path)));
    return {};
}

void ChangeLogView::save()
{
    QSettings settings;
    const QString folder =
        settings.value(QStringLiteral("changeLog/folder"), QDir::homePath()).toString();
    const QString suggested = folder + QLatin1Char('/')
        + QStringLiteral("changes-%1.csv")
              .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save change log"), suggested,
                                                      tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    settings.setValue(QStringLiteral("changeLog/folder"), QFileInfo(path).absolutePath());
    saveTo(path);
}

} // namespace db::widgets
