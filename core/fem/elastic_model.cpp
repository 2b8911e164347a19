#include "fem/elastic_model.h"

namespace sculpt {

const char* elasticModelName(ElasticModel model) {
  return model == ElasticModel::Corotated ? "corotated" : "barrier";
}

std::optional<ElasticModel> parseElasticModel(const std::string& name) {
  if (name == "corotated") return ElasticModel::Corotated;
  if (name == "barrier") return ElasticModel::Barrier;
  return std::nullopt;
}

}  // namespace sculpt
