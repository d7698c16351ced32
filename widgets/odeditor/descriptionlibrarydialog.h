#pragma once

// The description library as a list: our built-in descriptions and the files of the user's
// folder with the identity each is matched by (vendor, product, revision). Add… or a file dropped
// onto the dialog copies a description into the folder after checking that it loads
// (DescriptionLibrary::addFile); a file that does not load is named with its problem and not
// added.

#include "description/descriptionlibrary.h"

#include <QDialog>

class QLabel;
class QMimeData;
class QPushButton;
class QTreeWidget;

namespace db::widgets {

class DescriptionLibraryDialog : public QDialog
{
    Q_OBJECT
public:
    // The library must outlive the dialog; its folder is set by the caller.
    explicit DescriptionLibraryDialog(DescriptionLibrary &library, QWidget *parent = nullptr);

    QTreeWidget *list() const { return m_list; }
    QString status() const;

public Q_SLOTS:
    // Adds one file; the list and status line show the result.
    bool addFile(const QString &path);
    void refresh();

Q_SIGNALS:
    void fileAdded(const QString &libraryPath);

protected:
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void showStatus(const QString &text, bool error);

    DescriptionLibrary &m_library;
    QLabel *m_folder;
    QTreeWidget *m_list;
    QPushButton *m_add;
    QLabel *m_status;
};

} // namespace db::widgets
