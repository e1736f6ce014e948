// The run file as the runner's RunSink: frames, cycle ends and the step log are kept in memory
// and the whole file is rewritten atomically (PATH.tmp) at every checkpoint (run_file.hpp).
#pragma once

#include "sim/integrate/integrator.hpp"
#include "sim/io/run_file.hpp"

namespace crumple {

class FileSink : public RunSink {
 public:
  FileSink(RunRecord& record, std::string tmp_path, Integrator& integ, double crease_threshold)
      : rec_(record), path_(std::move(tmp_path)), integ_(integ), threshold_(crease_threshold) {}

  void frame(const State& s, const std::string& stage, int cycle) override {
    rec_.frames.push_back({s, stage, cycle, integ_.summary().steps()});
  }
  void stage_end(int cycle, int index, const std::string& type, const State& s) override {
    rec_.stage_ends.push_back({cycle, index, type, s.t, s.p});
  }
  void cycle_end(int cycle, const State& s) override {
    CycleRecord c;
    c.cycle = cycle;
    c.t = s.t;
    c.x = s.x;
    c.p = s.p;
    c.crease_threshold = threshold_;
    c.crease_mask.resize(s.p.size());
    for (Index h = 0; h < s.p.size(); ++h) c.crease_mask[h] = std::abs(s.p[h]) > threshold_;
    rec_.cycles.push_back(std::move(c));
  }
  void checkpoint(const Checkpoint& c) override {
    flush_log();
    rec_.checkpoint = c;
    write_run_file_atomic(path_, rec_);
  }
  void flush_log() {
    rec_.log.insert(rec_.log.end(), integ_.log().begin(), integ_.log().end());
    integ_.clear_log();
    rec_.summary = integ_.summary();  // cumulative: a resumed integrator restores its counters
  }

 private:
  RunRecord& rec_;
  std::string path_;
  Integrator& integ_;
  double threshold_;
};

}  // namespace crumple
