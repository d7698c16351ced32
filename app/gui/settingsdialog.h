#pragma once

#include <QDialog>
#include <QStringList>

class QCheckBox;
class QComboBox;
class QListWidget;
class QSpinBox;

namespace db::gui {

// File → Settings: the language of the window (from the next start), the time limits new
// connections get, the optional automatic reconnect, and the recent connections (remove some or
// all).
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
        // After a lost link, open it again every few seconds for up to reconnectWindowS.
        bool autoReconnect = false;
        int reconnectWindowS = 60;
    };

    explicit SettingsDialog(const Values &values, QWidget *parent = nullptr);
    Values values() const;

private:
    QComboBox *m_language;
    QSpinBox *m_connectTimeout;
    QSpinBox *m_requestTimeout;
    QCheckBox *m_autoReconnect;
    QSpinBox *m_reconnectWindow;
    QListWidget *m_recent;
};

} // namespace db::gui
