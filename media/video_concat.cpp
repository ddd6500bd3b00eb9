#include "media/video_concat.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <memory>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::media {
namespace {

struct InputCloser {
  void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};
using Input = std::unique_ptr<AVFormatContext, InputCloser>;

struct Segment {
  Input input;
  int stream = -1;
};

Segment open_segment(const std::filesystem::path& path) {
  AVFormatContext* raw = nullptr;
  if (avformat_open_input(&raw, path.c_str(), nullptr, nullptr) < 0)
    throw_input_error("{}: cannot open as a video", path.string());
  Segment s{Input(raw)};
  if (avformat_find_stream_info(raw, nullptr) < 0) throw_input_error("{}: no stream information", path.string());
  s.stream = av_find_best_stream(raw, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (s.stream < 0) throw_input_error("{}: no video stream", path.string());
  return s;
}

void require_same(const Segment& first, const Segment& s, const std::filesystem::path& path) {
  const AVCodecParameters* a = first.input->streams[first.stream]->codecpar;
  const AVCodecParameters* b = s.input->streams[s.stream]->codecpar;
  const AVRational ta = first.input->streams[first.stream]->time_base, tb = s.input->streams[s.stream]->time_base;
  if (a->codec_id != b->codec_id) throw_input_error("{}: codec differs from the first segment's", path.string());
  if (a->width != b->width || a->height != b->height)
    throw_input_error("{}: {}x{} differs from the first segment's {}x{}", path.string(), b->width, b->height,
                      a->width, a->height);
  if (a->format != b->format) throw_input_error("{}: pixel format differs from the first segment's", path.string());
  if (av_cmp_q(ta, tb) != 0) throw_input_error("{}: time base differs from the first segment's", path.string());
}

struct OutputCloser {
  void operator()(AVFormatContext* c) const {
    if (c->pb && !(c->oformat->flags & AVFMT_NOFILE)) avio_closep(&c->pb);
    avformat_free_context(c);
  }
};

long write_joined(std::vector<Segment>& segments, const std::filesystem::path& tmp, const std::string& name) {
  // The container from the final name (the temporary one ends in .tmpXXXX).
  const AVOutputFormat* format = av_guess_format(nullptr, name.c_str(), nullptr);
  if (!format) throw_input_error("{}: no container for this extension", name);
  AVFormatContext* raw = nullptr;
  if (avformat_alloc_output_context2(&raw, format, nullptr, tmp.c_str()) < 0 || !raw)
    throw_input_error("{}: cannot create", name);
  std::unique_ptr<AVFormatContext, OutputCloser> out(raw);
  const AVStream* in0 = segments[0].input->streams[segments[0].stream];
  AVStream* stream = avformat_new_stream(raw, nullptr);
  avcodec_parameters_copy(stream->codecpar, in0->codecpar);
  stream->codecpar->codec_tag = in0->codecpar->codec_tag;
  stream->time_base = in0->time_base;
  stream->avg_frame_rate = in0->avg_frame_rate;
  if (avio_open(&raw->pb, tmp.c_str(), AVIO_FLAG_WRITE) < 0) throw_input_error("{}: cannot create", name);
  if (avformat_write_header(raw, nullptr) < 0) throw_input_error("{}: cannot write the header", name);
  AVPacket* packet = av_packet_alloc();
  long frames = 0;
  int64_t offset = 0;  // in the segments' time base
  for (Segment& s : segments) {
    const AVRational in_base = s.input->streams[s.stream]->time_base;
    int64_t first_pts = AV_NOPTS_VALUE, end = offset;
    while (av_read_frame(s.input.get(), packet) >= 0) {
      if (packet->stream_index != s.stream) {
        av_packet_unref(packet);
        continue;
      }
      // Each segment's pictures start where the one before ended: its first packet is its
      // keyframe, the earliest picture (decode times before it stay below the last segment's).
      if (first_pts == AV_NOPTS_VALUE) first_pts = packet->pts != AV_NOPTS_VALUE ? packet->pts : packet->dts;
      const int64_t shift = offset - first_pts;
      if (packet->pts != AV_NOPTS_VALUE) packet->pts += shift;
      if (packet->dts != AV_NOPTS_VALUE) packet->dts += shift;
      end = std::max(end, (packet->pts != AV_NOPTS_VALUE ? packet->pts : packet->dts) + std::max<int64_t>(packet->duration, 1));
      packet->stream_index = 0;
      av_packet_rescale_ts(packet, in_base, stream->time_base);
      ++frames;
      if (av_interleaved_write_frame(raw, packet) < 0) {
        av_packet_free(&packet);
        throw std::runtime_error(name + ": write failed");
      }
    }
    offset = end;
  }
  av_packet_free(&packet);
  if (av_write_trailer(raw) < 0) throw std::runtime_error(name + ": cannot write the trailer");
  return frames;
}

}  // namespace

long concat_videos(const std::vector<std::filesystem::path>& paths, const std::filesystem::path& output) {
  if (paths.empty()) throw_input_error("{}: no segments to join", output.string());
  std::vector<Segment> segments;
  for (const auto& p : paths) {
    segments.push_back(open_segment(p));
    require_same(segments.front(), segments.back(), p);
  }
  long frames = 0;
  write_file_atomic(output, [&](const std::filesystem::path& tmp) { frames = write_joined(segments, tmp, output.string()); });
  return frames;
}

}  // namespace lfd::media
