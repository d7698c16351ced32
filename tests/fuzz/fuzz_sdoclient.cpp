// The SDO client's transfer state machines against a hostile server: the first byte chooses the
// transfer (expedited/segmented/block, upload/download), the rest are the server's 8-byte
// frames. A transfer must end (done or failed) or wait; it must never accept more data than it
// asked for or its size limit.
#include "canopen/sdoblocktransfer.h"
#include "canopen/sdotransfer.h"
#include "fuzzsupport.h"

#include <memory>

using namespace db;
using namespace db::canopen;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::Input in(data, size);
    const quint8 kind = in.byte();
    const ObjectAddress address { quint16(0x2000 + in.byte()), in.byte() };
    const QByteArray payload = in.chunk(200);
    std::unique_ptr<SdoTransfer> t;
    switch (kind % 5) {
    case 0:
        t = std::make_unique<SdoUpload>(address);
        break;
    case 1:
        t = std::make_unique<SdoDownload>(address, payload, false);
        break;
    case 2:
        t = std::make_unique<SdoDownload>(address, payload, true);
        break;
    case 3:
        t = std::make_unique<SdoBlockUpload>(address, 1 + (kind >> 3) % 127);
        break;
    default:
        t = std::make_unique<SdoBlockDownload>(address, payload);
        break;
    }
    SdoStep step = t->start();
    while (!in.atEnd() && step.outcome != SdoStep::Outcome::Done
           && step.outcome != SdoStep::Outcome::Failed) {
        QByteArray frame = in.take(8);
        frame.append(QByteArray(8 - frame.size(), '\0'));
        step = t->onFrame(frame);
        for (const QByteArray &f : step.frames)
            if (f.size() != 8)
                fuzz::finding("the SDO client would send a frame that is not 8 bytes");
        if (t->transferred() > SdoUpload::kMaxSize)
            fuzz::finding("an SDO upload grew past its size limit");
    }
    return 0;
}
