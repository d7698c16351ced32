// CanopenConnection: choosing the description of a node from its identity (CiA 301 7.5.2.18,
// 1018h) while the connection is still Connecting, so that nothing polls objects of a
// description that is about to change.
#include "canopenconnection.h"

#include "cannetwork.h"
#include "canopenlogging.h"

#include <QCoreApplication>

namespace {
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(db::canopen)
};

constexpr db::ObjectAddress kVendorId { 0x1018, 1 };
constexpr db::ObjectAddress kProductCode { 0x1018, 2 };
constexpr db::ObjectAddress kRevision { 0x1018, 3 };

quint32 u32(const QByteArray &bytes)
{
    quint32 v = 0;
    for (qsizetype i = qMin<qsizetype>(bytes.size(), 4) - 1; i >= 0; --i)
        v = (v << 8) | quint8(bytes.at(i));
    return v;
}
} // namespace

namespace db::canopen {

// Three expedited uploads in a row: vendor, product (both needed), revision (optional: an abort
// leaves it unknown). A timeout or abort on the first two ends the identification; the
// connection then connects without a description.
void CanopenConnection::identify()
{
    prepareSdo();
    auto numbers = std::make_shared<IdentityNumbers>();
    const auto upload = [this](ObjectAddress address) {
        Reply *r = m_network->sdo()->upload(m_node, address, SdoClient::Mode::Expedited, 4);
        r->setParent(this);
        return r;
    };
    const auto failed = [this](Reply *r) {
        return Tr::tr("node %1 did not report its identity (%2: %3)")
            .arg(m_node)
            .arg(r->address().toString(), r->error().toString());
    };
    Reply *vendor = upload(kVendorId);
    connect(vendor, &Reply::finished, this, [=, this] {
        vendor->deleteLater();
        if (state() != State::Connecting)
            return;
        if (!vendor->ok()) {
            onIdentified(std::nullopt, failed(vendor));
            return;
        }
        numbers->vendorId = u32(vendor->value().toByteArray());
        Reply *product = upload(kProductCode);
        connect(product, &Reply::finished, this, [=, this] {
            product->deleteLater();
            if (state() != State::Connecting)
                return;
            if (!product->ok()) {
                onIdentified(std::nullopt, failed(product));
                return;
            }
            numbers->productCode = u32(product->value().toByteArray());
            Reply *revision = upload(kRevision);
            connect(revision, &Reply::finished, this, [=, this] {
                revision->deleteLater();
                if (state() != State::Connecting)
                    return;
                if (revision->ok())
                    numbers->revision = u32(revision->value().toByteArray());
                onIdentified(*numbers, QString());
            });
        });
    });
}

void CanopenConnection::onIdentified(const std::optional<IdentityNumbers> &identity,
                                     const QString &why)
{
    m_identity = identity;
    if (identity) {
        DescriptionChoice choice = m_chooser(*identity, m_node);
        m_descriptionNote = choice.text;
        if (choice.dictionary && !choice.dictionary->isEmpty()) {
            setDictionary(*choice.dictionary);
        } else {
            // No description: the numbers stay visible (editor prompt, DCF export).
            ObjectDictionary numbersOnly;
            numbersOnly.identity.vendorId = identity->vendorId;
            numbersOnly.identity.productCode = identity->productCode;
            if (identity->revision)
                numbersOnly.identity.revision =
                    QStringLiteral("0x%1").arg(*identity->revision, 8, 16, QLatin1Char('0'));
            setDictionary(numbersOnly);
        }
    } else {
        m_descriptionNote = why;
    }
    qCInfo(lcCanopen).noquote() << m_descriptionNote;
    Q_EMIT logLine(m_descriptionNote);
    Q_EMIT logLine(Tr::tr("connected to node %1 on %2").arg(m_node).arg(m_network->name()));
    setState(State::Connected);
    watchHeartbeat();
}

} // namespace db::canopen
