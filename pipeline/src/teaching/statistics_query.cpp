#include "teaching/statistics_query.h"

#include <memory>

#include "teaching/per_context_table.h"

namespace glass::gl {
namespace {

PerContextTable<StatisticsQueries>& queriesTable() {
  static PerContextTable<StatisticsQueries> table;
  return table;
}

}  // namespace

StatisticsQueries& statisticsQueriesOf(const Context& ctx) {
  if (StatisticsQueries* found = queriesTable().find(ctx)) return *found;
  return queriesTable().attach(ctx, std::make_unique<StatisticsQueries>());
}

StatisticsQueries* findStatisticsQueries(const Context& ctx) { return queriesTable().find(ctx); }

void detachStatisticsQueries(const Context& ctx) { queriesTable().detach(ctx); }

}  // namespace glass::gl
