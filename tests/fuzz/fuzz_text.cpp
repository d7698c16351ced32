// Text the user types or scripts pass: connection URIs, object addresses in both formats (a
// parsed address must format and parse back to itself), values of every data type (a parsed
// value must print and parse back to the same raw value) and scope trigger specs.
#include "core/addressformat.h"
#include "core/connectionuri.h"
#include "core/datatype.h"
#include "core/valuecodec.h"
#include "fuzzsupport.h"
#include "scope/trigger.h"

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::Input in(data, size);
    const quint8 selector = in.byte();
    const QString text = QString::fromUtf8(in.rest());

    (void)ConnectionUri::parse(text);

    for (const AddressFormat *format : { &AddressFormat::canopen(), &AddressFormat::parameter() }) {
        const Result<ObjectAddress> a = format->parse(text);
        if (!a)
            continue;
        const Result<ObjectAddress> b = format->parse(format->format(*a));
        if (!b || *b != *a)
            fuzz::finding("an address does not survive format -> parse");
    }

    const QList<DataType> &types = datatype::all();
    const DataType type = types.at(selector % types.size());
    const Result<QVariant> v = codec::fromText(type, text);
    if (v) {
        const Result<QVariant> w = codec::fromText(type, codec::toText(type, *v));
        if (!w)
            fuzz::finding("a value does not parse after toText()");
        const Result<QByteArray> x = codec::encode(type, *v);
        const Result<QByteArray> y = codec::encode(type, *w);
        if (x && y && *x != *y)
            fuzz::finding("a value changed in toText -> fromText");
    }

    (void)scope::Trigger::parse(text, { QStringLiteral("6064:0"), QStringLiteral("6041:0") });
    return 0;
}
