// Brightness samples from a CSV file for the Morse decoder: the reader, then the decoder on
// what it accepted (small recordings only, so that one input stays fast).
#include "fuzzsupport.h"
#include "morse/decode/decoder.h"
#include "morse/input/morseinput.h"

#include <QBuffer>

using namespace db;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::ReadOnly);
    const Result<morseio::Recording> rec = morseio::readCsv(buffer, QStringLiteral("fuzz.csv"));
    if (!rec || rec->samples.size() > 20000)
        return 0;
    morse::Decoder decoder;
    decoder.feed(rec->samples);
    decoder.finish();
    (void)decoder.text().size();
    return 0;
}
