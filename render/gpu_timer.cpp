#include "render/gpu_timer.h"

#include <initializer_list>

namespace sculpt::render {

GpuTimer::GpuTimer() { glGenQueries(2, queries_); }

GpuTimer::~GpuTimer() { glDeleteQueries(2, queries_); }

void GpuTimer::begin() {
  if (pending_[current_]) lastMilliseconds();  // collect before reuse
  glBeginQuery(GL_TIME_ELAPSED, queries_[current_]);
}

void GpuTimer::end() {
  glEndQuery(GL_TIME_ELAPSED);
  pending_[current_] = true;
  current_ = 1 - current_;
}

double GpuTimer::lastMilliseconds() {
  for (int k : {current_, 1 - current_}) {  // the older query first
    if (!pending_[k]) continue;
    GLint available = 0;
    glGetQueryObjectiv(queries_[k], GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) continue;
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(queries_[k], GL_QUERY_RESULT, &nanoseconds);
    last_ = static_cast<double>(nanoseconds) * 1e-6;
    pending_[k] = false;
  }
  return last_;
}

}  // namespace sculpt::render
