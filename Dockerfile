# collide's runtime image, in two stages: the build stage compiles collide and packs the .deb;
# the runtime stage installs that .deb (and, through apt, only the libraries it depends on) and
# runs collide as a user without privileges.
#   docker build --build-arg COLLIDE_REVISION="$(git describe --always --dirty)" -t collide .
#   docker run --rm -v "$PWD:/work" -w /work collide thumbnail gas --at 2 -o gas.png
#   docker run --rm -v "$PWD:/work" -w /work collide compare golden/gas.png gas.png
# The image holds no compiler and no sources; docs/install.md gives its size. The tests run in
# the build stage's tree (scripts/test.sh), not in this image.
FROM debian:12 AS build
ENV DEBIAN_FRONTEND=noninteractive
WORKDIR /src
# The packages first, from the one file that lists them: an edit of the sources reuses this layer.
COPY scripts/setup.sh /src/scripts/setup.sh
RUN bash scripts/setup.sh && apt-get install -y -qq --no-install-recommends file && rm -rf /var/lib/apt/lists/*
COPY . /src
# The context has no .git (.dockerignore): the revision `collide --version` names comes from here.
ARG COLLIDE_REVISION=unknown
RUN cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOLLIDE_BUILD_TESTS=OFF -DCOLLIDE_BUILD_BENCH=OFF -DCOLLIDE_GIT_REVISION="$COLLIDE_REVISION" && cmake --build build/release && cpack -G DEB --config build/release/CPackConfig.cmake -B /deb && mv /deb/collide_*.deb /collide.deb

FROM debian:12
ENV DEBIAN_FRONTEND=noninteractive
COPY --from=build /collide.deb /tmp/collide.deb
# fonts-droid-fallback is only recommended by the .deb: named here, so that the image draws
# Chinese, Japanese and Korean text.
RUN apt-get update -qq && apt-get install -y -qq --no-install-recommends /tmp/collide.deb fonts-droid-fallback && rm -rf /var/lib/apt/lists/* /tmp/collide.deb && useradd --create-home --uid 1000 --shell /usr/sbin/nologin collide
USER collide
WORKDIR /home/collide
ENTRYPOINT ["collide"]
CMD ["--help"]
