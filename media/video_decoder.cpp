#include "media/video_decoder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/hwcontext.h>
#include <libavutil/imgutils.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include "util/error.hpp"

namespace lfd::media {
namespace {

std::string av_error_text(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

struct FrameFree {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
using FramePtr = std::unique_ptr<AVFrame, FrameFree>;
struct PacketFree {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};

// Bytes in memory read through an AVIOContext (the fuzz target, network callers).
struct MemoryInput {
  std::vector<uint8_t> bytes;
  int64_t pos = 0;

  static int read(void* opaque, uint8_t* buf, int size) {
    auto* in = static_cast<MemoryInput*>(opaque);
    const int64_t n = std::min<int64_t>(size, int64_t(in->bytes.size()) - in->pos);
    if (n <= 0) return AVERROR_EOF;
    std::memcpy(buf, in->bytes.data() + in->pos, size_t(n));
    in->pos += n;
    return int(n);
  }
  static int64_t seek(void* opaque, int64_t offset, int whence) {
    auto* in = static_cast<MemoryInput*>(opaque);
    const int64_t size = int64_t(in->bytes.size());
    if (whence & AVSEEK_SIZE) return size;
    int64_t target = offset;
    if ((whence & 3) == SEEK_CUR) target = in->pos + offset;
    if ((whence & 3) == SEEK_END) target = size + offset;
    if (target < 0 || target > size) return AVERROR(EINVAL);
    in->pos = target;
    return target;
  }
};

YuvMatrix matrix_of(AVColorSpace space, int height) {
  switch (space) {
    case AVCOL_SPC_BT709: return YuvMatrix::kBt709;
    case AVCOL_SPC_BT470BG:
    case AVCOL_SPC_SMPTE170M: return YuvMatrix::kBt601;
    case AVCOL_SPC_BT2020_NCL:
    case AVCOL_SPC_BT2020_CL: return YuvMatrix::kBt2020;
    default: return height >= 720 ? YuvMatrix::kBt709 : YuvMatrix::kBt601;  // unspecified: FFmpeg/mpv's guess
  }
}

// The hardware decoders tried, in order, before the software one (docs/arm.md "Video"): FFmpeg's
// hwaccels on a device — VA-API (x86 GPUs), DRM (Raspberry Pi OS's FFmpeg: the V4L2 request
// decoders of a Pi 4/5's HEVC block) — then a V4L2 memory-to-memory decoder (`h264_v4l2m2m`, ...:
// the stateful decoders of ARM boards, Pi 4's H.264 among them).
struct HwAccel {
  AVHWDeviceType type;
  AVPixelFormat format;  // what its frames are (downloaded before use)
  const char* name;
};
constexpr HwAccel kHwAccels[] = {{AV_HWDEVICE_TYPE_VAAPI, AV_PIX_FMT_VAAPI, "VA-API"},
                                 {AV_HWDEVICE_TYPE_DRM, AV_PIX_FMT_DRM_PRIME, "DRM (V4L2 request)"}};

// The hardware format of the context's accel (codec->opaque points to it), else the software one.
AVPixelFormat pick_hw_format(AVCodecContext* codec, const AVPixelFormat* formats) {
  const auto wanted = *static_cast<const AVPixelFormat*>(codec->opaque);
  for (const AVPixelFormat* f = formats; *f != AV_PIX_FMT_NONE; ++f)
    if (*f == wanted) return *f;
  return formats[0];  // the decoder's software format
}

// The first DRM render node ("" when there is none): VA-API and DRM devices need no display server.
std::string render_node() {
  std::string node;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/dev/dri", ec))
    if (entry.path().filename().string().rfind("renderD", 0) == 0 && (node.empty() || entry.path().string() < node))
      node = entry.path().string();
  return node;
}

// Whether a V4L2 video node exists (a memory-to-memory decoder is one).
bool has_video_node() {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/dev", ec))
    if (entry.path().filename().string().rfind("video", 0) == 0) return true;
  return false;
}

}  // namespace

struct VideoDecoder::Impl {
  std::string name;
  DecoderOptions options;
  VideoInfo info;
  std::string decode_path;
  std::unique_ptr<MemoryInput> memory;
  AVIOContext* io = nullptr;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVBufferRef* hw_device = nullptr;
  AVPixelFormat hw_format = AV_PIX_FMT_NONE;  // pick_hw_format's (codec->opaque)
  SwsContext* sws = nullptr;
  std::unique_ptr<AVPacket, PacketFree> packet{av_packet_alloc()};
  int stream = -1;
  AVRational time_base{1, 1};
  int64_t start_pts = 0;
  bool draining = false, ended = false;
  int64_t decoded = 0;
  std::optional<double> seek_target;  // frames before it are passed over
  std::optional<YuvFrame> pending;    // the frame read past a seek target

  ~Impl() {
    sws_freeContext(sws);
    avcodec_free_context(&codec);
    av_buffer_unref(&hw_device);
    avformat_close_input(&format);
    if (io) {
      av_freep(&io->buffer);
      avio_context_free(&io);
    }
  }

  void open(const char* url);
  void open_codec();
  void new_context(const AVCodec* decoder, int threads);
  bool open_hwaccel(const AVCodec* decoder, int threads, std::string& why);
  bool open_v4l2m2m(const AVCodec* decoder, std::string& why);
  FramePtr receive();
  YuvFrame to_yuv(FramePtr frame);
  std::optional<YuvFrame> next();
};

void VideoDecoder::Impl::open(const char* url) {
  // FFmpeg's own log would add lines to the one-line errors; its reasons are in them already.
  av_log_set_level(AV_LOG_FATAL);
  if (memory) {
    constexpr int kBuffer = 1 << 16;
    auto* buffer = static_cast<uint8_t*>(av_malloc(kBuffer));
    io = avio_alloc_context(buffer, kBuffer, 0, memory.get(), &MemoryInput::read, nullptr, &MemoryInput::seek);
    format = avformat_alloc_context();
    format->pb = io;
  }
  if (const int e = avformat_open_input(&format, url, nullptr, nullptr); e < 0)
    throw_input_error("{}: not a video FFmpeg can open ({})", name, av_error_text(e));
  if (const int e = avformat_find_stream_info(format, nullptr); e < 0)
    throw_input_error("{}: unreadable video ({})", name, av_error_text(e));
  stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (stream < 0) throw_input_error("{}: no video stream", name);
  for (unsigned i = 0; i < format->nb_streams; ++i)
    if (int(i) != stream) format->streams[i]->discard = AVDISCARD_ALL;  // audio ignored
  const AVStream* s = format->streams[stream];
  time_base = s->time_base;
  start_pts = s->start_time == AV_NOPTS_VALUE ? 0 : s->start_time;
  info.width = s->codecpar->width;
  info.height = s->codecpar->height;
  if (info.width < 1 || info.height < 1 || info.width > kMaxVideoSide || info.height > kMaxVideoSide)
    throw_input_error("{}: a {}x{} video is outside the bounds (1 to {} px a side)", name, info.width, info.height,
                      kMaxVideoSide);
  const AVRational rate = s->avg_frame_rate.num > 0 ? s->avg_frame_rate : s->r_frame_rate;
  info.frame_rate = rate.num > 0 && rate.den > 0 ? av_q2d(rate) : 0;
  if (!(info.frame_rate > 0 && info.frame_rate <= 1000)) info.frame_rate = 30;  // still images in a container
  if (s->duration != AV_NOPTS_VALUE && s->duration > 0) info.duration_s = double(s->duration) * av_q2d(time_base);
  else if (format->duration > 0) info.duration_s = double(format->duration) / AV_TIME_BASE;
  info.codec = avcodec_get_name(s->codecpar->codec_id);
  info.container = format->iformat ? format->iformat->name : "";
  open_codec();
}

void VideoDecoder::Impl::new_context(const AVCodec* decoder, int threads) {
  avcodec_free_context(&codec);
  codec = avcodec_alloc_context3(decoder);
  if (avcodec_parameters_to_context(codec, format->streams[stream]->codecpar) < 0)
    throw_input_error("{}: bad codec parameters", name);
  codec->pkt_timebase = time_base;
  codec->thread_count = threads;
  codec->thread_type = FF_THREAD_FRAME | FF_THREAD_SLICE;
}

bool VideoDecoder::Impl::open_hwaccel(const AVCodec* decoder, int threads, std::string& why) {
  // A device that failed once is not tried again for every video of a playlist.
  static std::mutex mutex;
  static std::map<AVHWDeviceType, std::string> failed;
  for (const HwAccel& accel : kHwAccels) {
    bool offered = false;
    for (int i = 0; const AVCodecHWConfig* config = avcodec_get_hw_config(decoder, i); ++i)
      offered |= (config->methods & AV_CODEC_HW_CONFIG_METHOD_HW_DEVICE_CTX) && config->device_type == accel.type;
    if (!offered) {
      why += fmt::format("; {}: none for {}", accel.name, info.codec);
      continue;
    }
    {
      std::lock_guard lock(mutex);
      if (!failed.count(accel.type)) {
        const std::string node = render_node();
        if (node.empty()) {
          failed[accel.type] = "no device (no /dev/dri render node)";
        } else if (const int e = av_hwdevice_ctx_create(&hw_device, accel.type, node.c_str(), nullptr, 0); e < 0) {
          failed[accel.type] = fmt::format("no device on {} ({})", node, av_error_text(e));
        }
      }
      if (failed.count(accel.type)) {
        why += fmt::format("; {}: {}", accel.name, failed[accel.type]);
        continue;
      }
    }
    new_context(decoder, threads);
    hw_format = accel.format;
    codec->opaque = &hw_format;
    codec->hw_device_ctx = av_buffer_ref(hw_device);
    codec->get_format = pick_hw_format;
    if (const int e = avcodec_open2(codec, decoder, nullptr); e < 0) {  // the decoder refused the device
      why += fmt::format("; {}: the decoder refused the device ({})", accel.name, av_error_text(e));
      avcodec_free_context(&codec);
      av_buffer_unref(&hw_device);
      continue;
    }
    decode_path = accel.name;
    return true;
  }
  return false;
}

bool VideoDecoder::Impl::open_v4l2m2m(const AVCodec* decoder, std::string& why) {
  const std::string m2m_name = std::string(decoder->name) + "_v4l2m2m";
  const AVCodec* m2m = avcodec_find_decoder_by_name(m2m_name.c_str());
  if (!m2m) {
    why += fmt::format("; V4L2 M2M: no {} in this FFmpeg", m2m_name);
    return false;
  }
  if (!has_video_node()) {
    why += "; V4L2 M2M: no /dev/video device";
    return false;
  }
  new_context(m2m, 1);
  if (const int e = avcodec_open2(codec, m2m, nullptr); e < 0) {
    why += fmt::format("; V4L2 M2M: {} did not open ({})", m2m_name, av_error_text(e));
    avcodec_free_context(&codec);
    return false;
  }
  decode_path = fmt::format("V4L2 M2M ({})", m2m_name);
  return true;
}

void VideoDecoder::Impl::open_codec() {
  const AVCodec* decoder = avcodec_find_decoder(format->streams[stream]->codecpar->codec_id);
  if (!decoder) throw_input_error("{}: no decoder for its codec '{}' in this FFmpeg", name, info.codec);
  const int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  // Hardware first when asked; each path that is not there says why, and software plays it.
  std::string why_software;
  if (options.try_hardware && (open_hwaccel(decoder, threads, why_software) || open_v4l2m2m(decoder, why_software)))
    return;
  new_context(decoder, threads);
  if (const int e = avcodec_open2(codec, decoder, nullptr); e < 0)
    throw_input_error("{}: cannot open the {} decoder ({})", name, info.codec, av_error_text(e));
  decode_path = fmt::format("software ({}, {} threads{})", decoder->name, threads, why_software);
}

FramePtr VideoDecoder::Impl::receive() {
  FramePtr frame(av_frame_alloc());
  while (true) {
    const int got = avcodec_receive_frame(codec, frame.get());
    if (got == 0) return frame;
    if (got == AVERROR_EOF) return nullptr;
    if (got != AVERROR(EAGAIN)) throw_input_error("{}: corrupt video frame ({})", name, av_error_text(got));
    if (draining) return nullptr;
    const int read = av_read_frame(format, packet.get());
    if (read == AVERROR_EOF || (read < 0 && avio_feof(format->pb))) {
      draining = true;
      avcodec_send_packet(codec, nullptr);
      continue;
    }
    if (read < 0) throw_input_error("{}: cannot read the video ({})", name, av_error_text(read));
    if (packet->stream_index == stream) {
      const int sent = avcodec_send_packet(codec, packet.get());
      if (sent < 0 && sent != AVERROR(EAGAIN) && sent != AVERROR_INVALIDDATA)
        throw_input_error("{}: corrupt video data ({})", name, av_error_text(sent));
    }
    av_packet_unref(packet.get());
  }
}

YuvFrame VideoDecoder::Impl::to_yuv(FramePtr frame) {
  if (hw_format != AV_PIX_FMT_NONE && frame->format == hw_format) {  // a hardware surface: download (NV12), then as any frame
    FramePtr cpu(av_frame_alloc());
    if (const int e = av_hwframe_transfer_data(cpu.get(), frame.get(), 0); e < 0)
      throw_input_error("{}: {} download failed ({})", name, decode_path, av_error_text(e));
    av_frame_copy_props(cpu.get(), frame.get());
    frame = std::move(cpu);
  }
  if (frame->width != info.width || frame->height != info.height)
    throw_input_error("{}: frame size changes mid-stream ({}x{} then {}x{})", name, info.width, info.height,
                      frame->width, frame->height);
  const auto format_now = AVPixelFormat(frame->format);
  const bool full = frame->color_range == AVCOL_RANGE_JPEG || format_now == AV_PIX_FMT_YUVJ420P;
  if (format_now != AV_PIX_FMT_YUV420P && format_now != AV_PIX_FMT_YUVJ420P) {
    sws = sws_getCachedContext(sws, frame->width, frame->height, format_now, frame->width, frame->height,
                               AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr, nullptr, nullptr);
    if (!sws) throw_input_error("{}: cannot convert its {} frames", name, av_get_pix_fmt_name(format_now));
    FramePtr planar(av_frame_alloc());
    planar->format = AV_PIX_FMT_YUV420P;
    planar->width = frame->width;
    planar->height = frame->height;
    av_frame_get_buffer(planar.get(), 0);
    av_frame_copy_props(planar.get(), frame.get());
    sws_scale(sws, frame->data, frame->linesize, 0, frame->height, planar->data, planar->linesize);
    frame = std::move(planar);
  }
  YuvFrame out;
  out.width = frame->width;
  out.height = frame->height;
  const int cw = (frame->width + 1) / 2, ch = (frame->height + 1) / 2;
  out.planes[0] = YuvPlane{frame->data[0], frame->linesize[0], frame->width, frame->height};
  out.planes[1] = YuvPlane{frame->data[1], frame->linesize[1], cw, ch};
  out.planes[2] = YuvPlane{frame->data[2], frame->linesize[2], cw, ch};
  out.matrix = matrix_of(frame->colorspace, frame->height);
  out.range = full ? YuvRange::kFull : YuvRange::kLimited;
  const int64_t pts = frame->best_effort_timestamp == AV_NOPTS_VALUE ? 0 : frame->best_effort_timestamp;
  out.pts_s = std::max(0.0, double(pts - start_pts) * av_q2d(time_base));
  out.index = std::llround(out.pts_s * info.frame_rate);
  out.storage = std::shared_ptr<const void>(frame.release(), [](const void* f) {
    auto* p = static_cast<AVFrame*>(const_cast<void*>(f));
    av_frame_free(&p);
  });
  return out;
}

std::optional<YuvFrame> VideoDecoder::Impl::next() {
  if (pending) {
    std::optional<YuvFrame> out = std::move(pending);
    pending.reset();
    return out;
  }
  std::optional<YuvFrame> before;  // while seeking: the last frame at or before the target
  while (!ended) {
    FramePtr frame = receive();
    if (!frame) {
      ended = true;
      break;
    }
    ++decoded;
    YuvFrame yuv = to_yuv(std::move(frame));
    if (!seek_target) return yuv;
    if (yuv.pts_s <= *seek_target + 1e-6) {
      before = std::move(yuv);
      continue;
    }
    seek_target.reset();
    if (!before) return yuv;  // the target lies before the first frame
    pending = std::move(yuv);
    return before;
  }
  seek_target.reset();
  return before;
}

VideoDecoder::VideoDecoder(const std::filesystem::path& path, const DecoderOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->name = path.string();
  impl_->options = options;
  if (!std::filesystem::is_regular_file(path)) throw_input_error("{}: file not found", impl_->name);
  impl_->open(impl_->name.c_str());
}

VideoDecoder::VideoDecoder(std::vector<uint8_t> bytes, const std::string& name, const DecoderOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->name = name;
  impl_->options = options;
  impl_->memory = std::make_unique<MemoryInput>();
  impl_->memory->bytes = std::move(bytes);
  impl_->open(nullptr);
}

VideoDecoder::~VideoDecoder() = default;

const VideoInfo& VideoDecoder::info() const { return impl_->info; }
const std::string& VideoDecoder::decode_path() const { return impl_->decode_path; }
const std::string& VideoDecoder::name() const { return impl_->name; }
int64_t VideoDecoder::frames_decoded() const { return impl_->decoded; }

std::optional<YuvFrame> VideoDecoder::next_frame() { return impl_->next(); }

void VideoDecoder::seek(double seconds) {
  Impl& d = *impl_;
  seconds = std::max(0.0, seconds);
  if (d.info.duration_s > 0) seconds = std::min(seconds, d.info.duration_s);
  const int64_t ts = d.start_pts + int64_t(std::floor(seconds / av_q2d(d.time_base)));
  if (const int e = av_seek_frame(d.format, d.stream, ts, AVSEEK_FLAG_BACKWARD); e < 0)
    throw_input_error("{}: cannot seek to {} s ({})", d.name, seconds, av_error_text(e));
  avcodec_flush_buffers(d.codec);
  d.draining = d.ended = false;
  d.pending.reset();
  d.seek_target = seconds;
}

}  // namespace lfd::media
