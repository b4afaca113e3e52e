#include "collide/show/puzzle_code.hpp"

namespace collide::show {

// The listings keep one line of pseudocode per line of source, as they read on screen.
// clang-format off
view::CodeView search_code(puzzle::Method method) {
    view::CodeView code;
    if (method == puzzle::Method::bfs) {
        code.title = "breadth-first search";
        code.lines = {{0, "insert the start"},
                      {0, "while the queue is not empty:"},
                      {1, "b = take the oldest out"},
                      {1, "if b is the goal: stop"},
                      {1, "for each neighbour n of b:"},
                      {2, "if n was seen: skip it"},
                      {2, "insert n at the back"}};
        return code;
    }
    code.title = "A* search";
    code.lines = {{0, "insert the start"},
                  {0, "while the queue is not empty:"},
                  {1, "b = delete the minimum"},
                  {1, "if b is the goal: stop"},
                  {1, "for each neighbour n of b:"},
                  {2, "if n is b's previous: skip"},
                  {2, "insert n, moves + h(n)"}};
    return code;
}
// clang-format on

std::vector<SearchLine> search_walk(const puzzle::SearchResult& r, std::size_t k) {
    const std::uint32_t id = r.expansions[k];
    if (id == r.goal) return {SearchLine::pop, SearchLine::goal};
    std::vector<SearchLine> walk{SearchLine::pop, SearchLine::goal, SearchLine::neighbours};
    // The start has no previous board; BFS skips every board seen before, which always includes
    // the previous one, so only the start's expansion walks straight to the insert.
    if (r.nodes[id].parent != puzzle::no_node) walk.push_back(SearchLine::skip);
    walk.push_back(SearchLine::insert);
    return walk;
}

}  // namespace collide::show
