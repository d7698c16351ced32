#include "descriptionlibrarydialog.h"

#include "descriptionprompt.h"
#include "widgets/common/widgetstyle.h"

#include <QDialogButtonBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMimeData>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace db::widgets {

namespace {
QString hex32(quint32 v)
{
    return QString::number(v, 16).rightJustified(8, QLatin1Char('0')).toUpper() + QLatin1Char('h');
}
} // namespace

DescriptionLibraryDialog::DescriptionLibraryDialog(DescriptionLibrary &library, QWidget *parent)
    : QDialog(parent)
    , m_library(library)
    , m_folder(new QLabel(this))
    , m_list(new QTreeWidget(this))
    , m_add(new QPushButton(tr("Add…"), this))
    , m_status(new QLabel(this))
{
    setWindowTitle(tr("Description Library"));
    setAcceptDrops(true);
    m_list->setObjectName(QStringLiteral("libraryList"));
    m_add->setObjectName(QStringLiteral("libraryAdd"));
    m_status->setObjectName(QStringLiteral("libraryStatus"));
    m_folder->setWordWrap(true);
    m_folder->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_list->setHeaderLabels(
        { tr("Name"), tr("Vendor"), tr("Product"), tr("Revision"), tr("File") });
    m_list->setRootIsDecorated(false);
    m_list->setAlternatingRowColors(true);
    m_list->header()->setStretchLastSection(true);
    m_add->setToolTip(tr("Copy a description file (EDS, DCF, XDD, XDC or drivebench JSON) into "
                         "the library folder; you can also drop files here"));

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_add, QDialogButtonBox::ActionRole);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_folder);
    layout->addWidget(m_list, 1);
    layout->addWidget(m_status);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_add, &QPushButton::clicked, this, [this] {
        const QStringList paths =
            QFileDialog::getOpenFileNames(this, tr("Add descriptions to the library"), QString(),
                                          DescriptionPrompt::fileFilter());
        for (const QString &path : paths)
            addFile(path);
    });
    refresh();
    resize(760, 420);
}

QString DescriptionLibraryDialog::status() const
{
    return m_status->text();
}

void DescriptionLibraryDialog::refresh()
{
    m_folder->setText(m_library.folder().isEmpty()
                          ? tr("No library folder is set; only the built-in descriptions are used.")
                          : tr("Devices without a description given get the one whose vendor, "
                               "product and revision match their identity (1018h). Your files "
                               "are in %1.")
                                .arg(m_library.folder()));
    m_add->setEnabled(!m_library.folder().isEmpty());
    m_list->clear();
    for (const LibraryEntry &e : m_library.entries()) {
        const bool builtin = !QFileInfo(e.origin).isFile();
        auto *item = new QTreeWidgetItem(
            m_list,
            { e.name, hex32(e.vendorId), e.productCode ? hex32(*e.productCode) : tr("any"),
              e.revision ? hex32(*e.revision) : tr("any"),
              builtin ? tr("built-in") : QFileInfo(e.origin).fileName() });
        item->setToolTip(4, e.origin);
    }
    for (int c = 0; c < 4; ++c)
        m_list->resizeColumnToContents(c);
    const QStringList warnings = m_library.warnings();
    if (!warnings.isEmpty())
        showStatus(tr("Not used: %1").arg(warnings.join(QStringLiteral("; "))), true);
}

bool DescriptionLibraryDialog::addFile(const QString &path)
{
    auto added = m_library.addFile(path);
    if (!added) {
        showStatus(tr("%1 not added: %2").arg(QFileInfo(path).fileName(), added.error().message()),
                   true);
        return false;
    }
    refresh();
    showStatus(tr("%1 added to the library").arg(QFileInfo(path).fileName()), false);
    Q_EMIT fileAdded(*added);
    return true;
}

void DescriptionLibraryDialog::dragEnterEvent(QDragEnterEvent *event)
{
    if (!DescriptionPrompt::droppedDescription(event->mimeData()).isEmpty()
        && !m_library.folder().isEmpty())
        event->acceptProposedAction();
}

void DescriptionLibraryDialog::dropEvent(QDropEvent *event)
{
    const QString path = DescriptionPrompt::droppedDescription(event->mimeData());
    if (path.isEmpty())
        return;
    event->acceptProposedAction();
    addFile(path);
}

void DescriptionLibraryDialog::showStatus(const QString &text, bool error)
{
    m_status->setText(text);
    style::setTextColor(m_status, error ? style::errorColor() : style::okColor());
}

} // namespace db::widgets
