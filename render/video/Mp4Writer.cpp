#include "render/video/Mp4Writer.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace rv {

struct Mp4Writer::Impl {
  explicit Impl(const std::string& path, const std::string& what) : file(path, what) {}
  ~Impl() {
    if (sws) sws_freeContext(sws);
    av_packet_free(&pkt);
    av_frame_free(&frame);
    avcodec_free_context(&enc);
    if (fmt) {
      if (fmt->pb) avio_closep(&fmt->pb);
      avformat_free_context(fmt);
    }
  }
  void encode(AVFrame* f) {
    if (avcodec_send_frame(enc, f) < 0) throw ComputationError("the video encoder refused a frame");
    while (avcodec_receive_packet(enc, pkt) == 0) {
      if (pkt->duration == 0) pkt->duration = 1; // else the file is one frame short
      av_packet_rescale_ts(pkt, enc->time_base, st->time_base);
      pkt->stream_index = st->index;
      if (av_interleaved_write_frame(fmt, pkt) < 0) throw ComputationError("cannot write " + file.path());
    }
  }
  AtomicFile file;
  int w = 0, h = 0;
  long next = 0;
  bool finished = false;
  AVFormatContext* fmt = nullptr;
  AVStream* st = nullptr;
  AVCodecContext* enc = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* pkt = nullptr;
  SwsContext* sws = nullptr;
};

Mp4Writer::Mp4Writer(const std::string& path, int width, int height, int fps, const EncoderSettings& encoder,
                     const std::string& what) {
  if (width < 16 || height < 16 || width % 2 || height % 2)
    throw InputError("--size " + std::to_string(width) + "x" + std::to_string(height) +
                     ": a video needs an even width and height of at least 16");
  if (fps < 1 || fps > 240) throw InputError("--fps " + std::to_string(fps) + ": must lie in [1, 240]");
  av_log_set_level(AV_LOG_ERROR); // libx264's banner is noise for users
  impl_ = std::make_unique<Impl>(path, what);
  Impl& m = *impl_;
  m.w = width, m.h = height;
  const AVCodec* codec = avcodec_find_encoder_by_name(encoder.codec.c_str());
  if (!codec) codec = avcodec_find_encoder(AV_CODEC_ID_MPEG4); // always built into libavcodec
  if (avformat_alloc_output_context2(&m.fmt, nullptr, "mp4", m.file.tempPath().c_str()) < 0)
    throw ComputationError("libav has no mp4 muxer");
  m.st = avformat_new_stream(m.fmt, nullptr);
  m.enc = avcodec_alloc_context3(codec);
  m.enc->width = width, m.enc->height = height;
  m.enc->pix_fmt = AV_PIX_FMT_YUV420P;
  m.enc->time_base = AVRational{1, fps};
  m.enc->framerate = AVRational{fps, 1};
  m.enc->gop_size = 2 * fps;
  if (codec->id == AV_CODEC_ID_H264) {
    if (av_opt_set(m.enc->priv_data, "preset", encoder.preset.c_str(), 0) < 0)
      throw InputError("video.preset: x264 has no preset '" + encoder.preset + "'");
    av_opt_set_int(m.enc->priv_data, "crf", encoder.crf, 0);
  } else {
    m.enc->bit_rate = 6000000;
  }
  if (m.fmt->oformat->flags & AVFMT_GLOBALHEADER) m.enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if (avcodec_open2(m.enc, codec, nullptr) < 0) throw ComputationError("cannot open the video encoder");
  avcodec_parameters_from_context(m.st->codecpar, m.enc);
  m.st->time_base = m.enc->time_base;
  m.st->avg_frame_rate = m.enc->framerate;
  if (avio_open(&m.fmt->pb, m.file.tempPath().c_str(), AVIO_FLAG_WRITE) < 0)
    throw ComputationError("cannot open " + m.file.tempPath() + " for writing");
  if (avformat_write_header(m.fmt, nullptr) < 0) throw ComputationError("cannot write the MP4 header");
  m.frame = av_frame_alloc();
  m.frame->format = m.enc->pix_fmt, m.frame->width = width, m.frame->height = height;
  av_frame_get_buffer(m.frame, 0);
  m.sws = sws_getContext(width, height, AV_PIX_FMT_RGB24, width, height, AV_PIX_FMT_YUV420P, SWS_BICUBIC,
                         nullptr, nullptr, nullptr);
  m.pkt = av_packet_alloc();
}

Mp4Writer::~Mp4Writer() = default; // Impl frees libav; AtomicFile removes an unfinished file

void Mp4Writer::add(const unsigned char* rgb) {
  Impl& m = *impl_;
  av_frame_make_writable(m.frame);
  const uint8_t* src[1] = {rgb};
  const int stride[1] = {m.w * 3};
  sws_scale(m.sws, src, stride, 0, m.h, m.frame->data, m.frame->linesize);
  m.frame->pts = m.next++;
  m.encode(m.frame);
}

void Mp4Writer::finish() {
  Impl& m = *impl_;
  if (m.finished) return;
  m.encode(nullptr); // drain delayed frames
  if (av_write_trailer(m.fmt) < 0) throw ComputationError("cannot finish " + m.file.path());
  avio_closep(&m.fmt->pb);
  m.file.commit();
  m.finished = true;
}

const char* Mp4Writer::codecName() const {
  return impl_->enc->codec->name;
}
long Mp4Writer::frames() const {
  return impl_->next;
}

std::string libavVersions() {
  auto version = [](const char* name, unsigned v) {
    return std::string(name) + " " + std::to_string(v >> 16) + "." + std::to_string((v >> 8) & 0xff) + "." +
           std::to_string(v & 0xff);
  };
  return version("libavcodec", avcodec_version()) + ", " + version("libavformat", avformat_version()) + ", " +
         version("libswscale", swscale_version());
}

} // namespace rv
