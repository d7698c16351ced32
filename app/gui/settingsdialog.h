#pragma once

#include <QDialog>
#include <QStringList>

class QComboBox;
class QListWidget;
class QSpinBox;

namespace db::gui {

// File → Settings: the language of the window (from the next start), the time limits new
// connections get, and the recent connections (remove some or all).
class SettingsDialog : public QDialog
{
    Q_OBJECT
public:
    struct Values
    {
        QString language; // "" follows the system, else "en" or "de"
        int connectTimeoutMs = 3000;
        int requestTimeoutMs = 1000;
        QStringList recent;
    };

    explicit SettingsDialog(const Values &values, QWidget *parent = nullptr);
    Values values() const;

private:
    QComboBox *m_language;
    QSpinBox *m_connectTimeout;
    QSpinBox *m_requestTimeout;
    QListWidget *m_recent;
};

} // namespace db::gui
