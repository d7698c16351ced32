#pragma once

#include <QAbstractTableModel>
#include <QPointer>
#include <QWidget>

class QLabel;
class QTableView;

namespace db {
class ChangeLog;
}

namespace db::widgets {

// The change log as a table (time, action, object, old → new, result, stored, device), newest
// at the bottom, with writes that a permanent store would keep but has not yet marked.
class ChangeLogModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { Time, Action, Object, OldValue, NewValue, Result, Stored, Device, ColumnCount };

    explicit ChangeLogModel(ChangeLog *log, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    QPointer<ChangeLog> m_log;
};

// The Changes dock: the table, how many writes are not stored, Save… (CSV) and Clear.
class ChangeLogView : public QWidget
{
    Q_OBJECT
public:
    explicit ChangeLogView(ChangeLog *log, QWidget *parent = nullptr);

    ChangeLogModel *model() const { return m_model; }
    QTableView *table() const { return m_table; }
    // Saves the log as CSV to `path`; an empty string on success, else the cause (also shown).
    QString saveTo(const QString &path);

private:
    void save();
    void updateSummary();

    ChangeLog *m_log;
    ChangeLogModel *m_model;
    QTableView *m_table;
    QLabel *m_summary;
};

} // namespace db::widgets
