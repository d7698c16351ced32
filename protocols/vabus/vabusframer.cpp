#include "vabusframer.h"

namespace db::vabus {

namespace {

Frame garbage(const QByteArray &bytes, const QString &problem)
{
    return Frame { Frame::Kind::Garbage, {}, bytes, problem };
}

} // namespace

std::vector<Result<Frame>> Framer::feed(const QByteArray &bytes)
{
    std::vector<Result<Frame>> out;
    m_buffer.append(bytes);
    while (!m_buffer.isEmpty()) {
        const quint8 header = quint8(m_buffer.at(0));
        if (header == kNak) {
            out.push_back(
                Frame { Frame::Kind::Nak, {}, m_buffer.left(1), QStringLiteral("NAK (0x15)") });
            m_buffer.remove(0, 1);
            continue;
        }
        if (header & ~(kRwBit | kErrorBit)) {
            out.push_back(garbage(std::exchange(m_buffer, {}),
                                  QStringLiteral("header byte 0x%1 is no VABus header")
                                      .arg(header, 2, 16, QLatin1Char('0'))));
            break;
        }
        if (m_buffer.size() < 2)
            break;
        const int nob = quint8(m_buffer.at(1));
        if (nob < kAddressBytes || nob > kMaxNob) {
            out.push_back(garbage(std::exchange(m_buffer, {}),
                                  QStringLiteral("NoB %1 is outside %2..%3")
                                      .arg(nob)
                                      .arg(kAddressBytes)
                                      .arg(kMaxNob)));
            break;
        }
        if (m_buffer.size() < nob + 2)
            break;
        const QByteArray frame = m_buffer.left(nob + 2);
        auto telegram = decode(frame);
        if (!telegram) {
            out.push_back(garbage(std::exchange(m_buffer, {}), telegram.error().message()));
            break;
        }
        m_buffer.remove(0, nob + 2);
        out.push_back(Frame { Frame::Kind::Telegram, telegram.value(), frame, {} });
    }
    return out;
}

} // namespace db::vabus
