#include "engine/response.h"

namespace collide {

const char* model_name(Model m) {
    switch (m) {
        case Model::frictionless: return "frictionless";
        case Model::coulomb: return "coulomb";
        case Model::matrix: return "matrix";
        case Model::stick: return "stick";
        case Model::page_listing: return "page-listing";
        case Model::routh: return "routh";
    }
    return "?";
}

bool parse_model(const std::string& name, Model* out) {
    for (Model m :
         {Model::frictionless, Model::coulomb, Model::matrix, Model::stick, Model::page_listing, Model::routh}) {
        if (name == model_name(m)) {
            *out = m;
            return true;
        }
    }
    return false;
}

}  // namespace collide
