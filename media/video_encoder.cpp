#include "media/video_encoder.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "util/error.hpp"

namespace lfd::media {

void check_video_size(const std::string& codec, int width, int height, const std::string& what) {
  if (width < 16 || height < 16 || width % 2 || height % 2)
    throw_input_error("{}: video frames of {}x{} must have even sides of at least 16 pixels", what, width, height);
  // H.264 and H.265 level 6.2: MaxFS 139264 macroblocks (35,651,584 luma samples); x264 and x265
  // refuse sides over 16384.
  constexpr long long kMaxPixels = 35651584;
  const bool avc_or_hevc = codec == "libx264" || codec == "libx265";
  if (avc_or_hevc && (static_cast<long long>(width) * height > kMaxPixels || width > 16384 || height > 16384))
    throw_input_error("{}: video frames of {}x{} exceed what {} encodes (level 6.2: {} pixels, sides up to 16384); "
                      "make the views smaller (--size)",
                      what, width, height, codec, kMaxPixels);
}

struct VideoEncoder::Impl {
  std::string name;
  EncoderOptions options;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = av_packet_alloc();
  int64_t next_pts = 0;
  bool finished = false;

  ~Impl() {
    av_frame_free(&frame);
    av_packet_free(&packet);
    sws_freeContext(sws);
    avcodec_free_context(&codec);
    if (format && !(format->oformat->flags & AVFMT_NOFILE)) avio_closep(&format->pb);
    avformat_free_context(format);
  }

  void write_packets(AVFrame* input) {
    if (avcodec_send_frame(codec, input) < 0) throw std::runtime_error(name + ": the encoder refused a frame");
    while (avcodec_receive_packet(codec, packet) == 0) {
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      if (av_interleaved_write_frame(format, packet) < 0) throw std::runtime_error(name + ": write failed");
    }
  }
};

VideoEncoder::VideoEncoder(const std::filesystem::path& path, const EncoderOptions& o) : impl_(std::make_unique<Impl>()) {
  Impl& e = *impl_;
  e.name = path.string();
  e.options = o;
  check_video_size(o.codec, o.width, o.height, e.name);
  av_log_set_level(AV_LOG_ERROR);  // x264 prints its statistics at info level
  if (avformat_alloc_output_context2(&e.format, nullptr, nullptr, e.name.c_str()) < 0 || !e.format)
    throw_input_error("{}: no container for this extension", e.name);
  const AVCodec* encoder = avcodec_find_encoder_by_name(o.codec.c_str());
  if (!encoder) throw_input_error("{}: no encoder '{}' in this FFmpeg", e.name, o.codec);
  e.stream = avformat_new_stream(e.format, nullptr);
  e.codec = avcodec_alloc_context3(encoder);
  AVCodecContext* c = e.codec;
  c->width = o.width;
  c->height = o.height;
  c->time_base = AVRational{1, o.frame_rate};
  c->framerate = AVRational{o.frame_rate, 1};
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->gop_size = o.gop > 0 ? o.gop : o.frame_rate;
  c->colorspace = AVCOL_SPC_BT709;
  c->color_primaries = AVCOL_PRI_BT709;
  c->color_trc = AVCOL_TRC_BT709;
  c->color_range = AVCOL_RANGE_MPEG;
  if (e.format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  av_opt_set(c->priv_data, "preset", o.preset.c_str(), 0);
  av_opt_set_int(c->priv_data, "crf", o.crf, 0);
  av_opt_set(c->priv_data, "x265-params", "log-level=error", 0);  // x265 logs on its own otherwise
  if (avcodec_open2(c, encoder, nullptr) < 0) throw_input_error("{}: cannot open the {} encoder", e.name, o.codec);
  avcodec_parameters_from_context(e.stream->codecpar, c);
  // Apple's players and browsers take H.265 in MP4 only under the hvc1 tag.
  if (c->codec_id == AV_CODEC_ID_HEVC) e.stream->codecpar->codec_tag = MKTAG('h', 'v', 'c', '1');
  e.stream->time_base = c->time_base;
  e.stream->avg_frame_rate = c->framerate;
  if (!(e.format->oformat->flags & AVFMT_NOFILE) && avio_open(&e.format->pb, e.name.c_str(), AVIO_FLAG_WRITE) < 0)
    throw_input_error("{}: cannot create", e.name);
  AVDictionary* muxer_options = nullptr;
  if (o.fragmented) av_dict_set(&muxer_options, "movflags", "frag_keyframe+empty_moov+default_base_moof", 0);
  const int header = avformat_write_header(e.format, &muxer_options);
  av_dict_free(&muxer_options);
  if (header < 0) throw_input_error("{}: cannot write the header", e.name);
  e.sws = sws_getContext(o.width, o.height, AV_PIX_FMT_RGB24, o.width, o.height, AV_PIX_FMT_YUV420P, SWS_BICUBIC,
                         nullptr, nullptr, nullptr);
  // RGB -> BT.709 limited range (what the stream is tagged with).
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(e.sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  e.frame = av_frame_alloc();
  e.frame->format = AV_PIX_FMT_YUV420P;
  e.frame->width = o.width;
  e.frame->height = o.height;
  av_frame_get_buffer(e.frame, 0);
}

VideoEncoder::~VideoEncoder() {
  if (impl_ && !impl_->finished) try {
      finish();
    } catch (const std::exception&) {
    }
}

void VideoEncoder::add_frame(const Image8& rgb) {
  Impl& e = *impl_;
  if (rgb.width != e.options.width || rgb.height != e.options.height || rgb.channels != 3)
    throw std::invalid_argument(e.name + ": frame size differs from the video's");
  av_frame_make_writable(e.frame);
  const uint8_t* src[1] = {rgb.pixels.data()};
  const int stride[1] = {rgb.width * 3};
  sws_scale(e.sws, src, stride, 0, rgb.height, e.frame->data, e.frame->linesize);
  e.frame->pts = e.next_pts++;
  e.write_packets(e.frame);
}

void VideoEncoder::finish() {
  Impl& e = *impl_;
  if (e.finished) return;
  e.finished = true;
  e.write_packets(nullptr);
  av_write_trailer(e.format);
}

}  // namespace lfd::media
