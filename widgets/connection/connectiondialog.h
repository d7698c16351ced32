#pragma once

#include "core/protocolregistry.h"
#include "description/descriptionlibrary.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QSpinBox;

namespace db::widgets {

// Asks for a connection URI: either built from protocol + address + port + options, or typed
// freely, or picked from the recent connections. For CANopen the address is an interface of the
// protocol's Qt CAN plugin (offered from QCanBus::availableDevices()) or the host of an SLCAN
// gateway, and node id, bit rate and description are fields of their own; they edit the
// node=, bitrate= and eds= options, so the options line and the URI stay the truth. The URI is
// checked with ProtocolRegistry::parseUri() on every change (cheap: nothing is read or opened); the
// error is shown inline and OK stays disabled while it is invalid. OK prepares the connection plan
// (loads the description the URI names) and stays open with the cause when that fails. The
// dialog never opens a connection.
class ConnectionDialog : public QDialog
{
    Q_OBJECT
public:
    static constexpr int kMaxRecent = 10;

    ConnectionDialog(const ProtocolRegistry &registry, const QStringList &recent,
                     QWidget *parent = nullptr);

    // The canonical URI (default port filled in); empty while the input is invalid.
    QString uri() const;
    bool isValid() const { return !m_validUri.isEmpty(); }
    QString errorText() const;
    // Puts a URI into the free line and the fields (e.g. from --connect or a recent entry).
    void setUri(const QString &uri);

    // The description files the user may pick for a CANopen node (entries that are not files are
    // left out: the library gives those by identity). "Automatic by identity" stays the default.
    void setDescriptionEntries(const QList<LibraryEntry> &entries);
    // A description file dropped onto the dialog becomes the description (eds=) of the URI.
    bool useDroppedDescription(const QString &path);

    // The prepared plan (after exec() returned Accepted).
    const ConnectionPlan &plan() const { return m_plan; }
    // Prepares the plan; accepts only when that works.
    void accept() override;

    // The recent list with uri() in front (after exec() returned Accepted).
    QStringList recentUris() const;
    // `uri` moved to the front of `recent`, duplicates removed, at most kMaxRecent entries.
    static QStringList withRecent(QStringList recent, const QString &uri);

protected:
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void onProtocolChanged();
    void buildUriFromFields();
    void fillFieldsFromUri();
    void validate();
    void createCanopenFields();
    void updateCanopenFields(const ProtocolInfo *info);
    void fillCanopenFields(const ConnectionUri &uri);
    // Sets (or, with an empty value, removes) key=value in the options line, then the URI.
    void setOption(const QString &key, const QString &value);
    void chooseDescriptionFile();
    int descriptionIndexOf(const QString &path);
    // Makes `path` the current choice (added to the list when it is none of its files).
    void selectDescription(const QString &path);

    const ProtocolRegistry &m_registry;
    QStringList m_recent;
    QString m_validUri;
    ConnectionPlan m_plan;
    bool m_updating = false;

    QComboBox *m_protocol;
    QLabel *m_patternHint;
    QComboBox *m_hostBox; // editable; its line edit is m_host, its list the CAN interfaces
    QLineEdit *m_host;
    QSpinBox *m_port;
    QSpinBox *m_node = nullptr;
    QComboBox *m_bitrate = nullptr;
    QComboBox *m_description = nullptr;
    QLineEdit *m_options;
    QLineEdit *m_uri;
    QLabel *m_error;
    QListWidget *m_recentList;
    QFormLayout *m_form = nullptr;
    QDialogButtonBox *m_buttons;
};

} // namespace db::widgets
