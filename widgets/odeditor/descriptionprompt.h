#pragma once

#include "core/deviceconnection.h"

#include <QFrame>

class QLabel;
class QMimeData;
class QPushButton;

namespace db::widgets {

// The bar the object editor shows instead of an empty table when a connected device has no
// description (none given, none in the library matches its identity): what is known of the
// device, and Browse… to pick its EDS/DCF/XDD/XDC/JSON file, or a file dropped onto the bar.
class DescriptionPrompt : public QFrame
{
    Q_OBJECT
public:
    explicit DescriptionPrompt(QWidget *parent = nullptr);

    // Visible while `connection` is connected with an empty dictionary; hidden otherwise.
    void showFor(const DeviceConnection *connection);
    // A problem with the file the user picked, shown until the next showFor().
    void showProblem(const QString &text);
    QString text() const;

    // The file filter of the Browse… dialog.
    static QString fileFilter();
    // The one local description file (by its suffix) among dropped URLs; empty otherwise.
    static QString droppedDescription(const QMimeData *data);

Q_SIGNALS:
    // The user picked a file in the Browse… dialog or dropped one onto the bar.
    void fileChosen(const QString &path);

protected:
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    QLabel *m_text;
    QPushButton *m_browse;
};

} // namespace db::widgets
