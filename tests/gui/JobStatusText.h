// JobStatusText.h -- QCOMPARE on job statuses prints their names. QTest finds a `toString` next to the type
// (argument-dependent lookup) and frees what it returns with delete[], so it must be a new copy (qstrdup):
// a static name there is freed and aborts the test run.
#pragma once
#include "dynamics/jobs/Job.h"

#include <QtGlobal>

namespace rv {
inline char* toString(Job::Status status) {
  return qstrdup(statusName(status));
}
} // namespace rv
