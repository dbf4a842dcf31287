// SPDX-License-Identifier: MIT
// Messages: the console line a user reads, the JSON line a tool reads, and the log that keeps
// them, from several threads at once.
#include "core/Message.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace stroma {
namespace {

Message fullMessage() {
  Message m;
  m.level = MessageLevel::error;
  m.text = "expected a value >= 0, got -1";
  m.componentPath = "/root/Liver/FEM";
  m.componentClass = "TetrahedronFEMForceField";
  m.field = "youngModulus";
  m.where = {"scene.scn", 12};
  return m;
}

TEST(LevelName, NamesEveryLevel) {
  EXPECT_STREQ(levelName(MessageLevel::info), "info");
  EXPECT_STREQ(levelName(MessageLevel::warning), "warning");
  EXPECT_STREQ(levelName(MessageLevel::error), "error");
}

TEST(FormatForConsole, NamesFileLineComponentClassAndField) {
  EXPECT_EQ(formatForConsole(fullMessage()),
            "scene.scn:12: error: /root/Liver/FEM (TetrahedronFEMForceField), field "
            "'youngModulus': expected a value >= 0, got -1");
}

TEST(FormatForConsole, LeavesOutWhatIsUnknown) {
  Message m = fullMessage();
  m.field.clear();
  EXPECT_EQ(formatForConsole(m),
            "scene.scn:12: error: /root/Liver/FEM (TetrahedronFEMForceField): expected a value "
            ">= 0, got -1");
  m.where.line = 0;
  m.level = MessageLevel::warning;
  m.componentClass.clear();
  m.text = "slow";
  EXPECT_EQ(formatForConsole(m), "scene.scn: warning: /root/Liver/FEM: slow");
  m.where.file.clear();
  m.componentPath.clear();
  m.level = MessageLevel::info;
  EXPECT_EQ(formatForConsole(m), "info: slow");
  m.field = "dt";
  EXPECT_EQ(formatForConsole(m), "info: field 'dt': slow");
  m.componentClass = "Node";
  EXPECT_EQ(formatForConsole(m), "info: ? (Node), field 'dt': slow");
}

TEST(FormatAsJson, WritesEveryKeyOnOneLine) {
  EXPECT_EQ(formatAsJson(fullMessage()),
            "{\"level\":\"error\",\"text\":\"expected a value >= 0, got -1\",\"component\":"
            "\"/root/Liver/FEM\",\"class\":\"TetrahedronFEMForceField\",\"field\":"
            "\"youngModulus\",\"file\":\"scene.scn\",\"line\":12}");
  EXPECT_EQ(formatAsJson(Message{}),
            "{\"level\":\"info\",\"text\":\"\",\"component\":\"\",\"class\":\"\",\"field\":"
            "\"\",\"file\":\"\",\"line\":0}");
}

TEST(FormatAsJson, EscapesQuotesBackslashesNewlinesAndControlCharacters) {
  Message m;
  m.text = std::string("say \"hi\"\\ok\nnext\r\tend\x01\x1f") + '\0' + "\x7f" + "\xc3\xa9";
  m.where.file = "C:\\scenes\\a \"b\".scn";
  const std::string json = formatAsJson(m);
  EXPECT_NE(json.find("\"text\":\"say \\\"hi\\\"\\\\ok\\nnext\\r\\tend\\u0001\\u001f\\u0000\x7f"
                      "\xc3\xa9\""),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"file\":\"C:\\\\scenes\\\\a \\\"b\\\".scn\""), std::string::npos) << json;
  for (char c : json) EXPECT_GE(static_cast<unsigned char>(c), 0x20) << "raw control in " << json;
}

// Collects what a log forwards.
struct Collector : MessageSink {
  std::vector<Message> received;
  void receive(const Message& message) override { received.push_back(message); }
};

TEST(MessageLog, KeepsCountsAndForwardsToSinks) {
  MessageLog log;
  auto sink = std::make_shared<Collector>();
  log.addSink(sink);
  Message m;
  m.text = "a";
  log.add(m);
  m.level = MessageLevel::warning;
  m.text = "b";
  log.add(m);
  m.level = MessageLevel::error;
  m.text = "c";
  log.add(m);
  log.add(m);
  EXPECT_EQ(log.count(MessageLevel::info), 1u);
  EXPECT_EQ(log.count(MessageLevel::warning), 1u);
  EXPECT_EQ(log.errorCount(), 2u);
  const auto all = log.messages();
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[1].text, "b");
  ASSERT_EQ(sink->received.size(), 4u);
  EXPECT_EQ(sink->received[2].text, "c");
  log.clear();
  EXPECT_EQ(log.errorCount(), 0u);
  EXPECT_TRUE(log.messages().empty());
  log.add(m);  // sinks survive clear()
  EXPECT_EQ(sink->received.size(), 5u);
}

TEST(StreamSink, WritesLinesAtOrAboveItsLevel) {
  std::ostringstream out;
  MessageLog log;
  log.addSink(std::make_shared<StreamSink>(out, MessageLevel::warning));
  Message m;
  m.text = "quiet";
  log.add(m);
  m.level = MessageLevel::warning;
  m.text = "loud";
  log.add(m);
  log.add(fullMessage());
  EXPECT_EQ(out.str(), "warning: loud\n" + formatForConsole(fullMessage()) + "\n");
}

TEST(JsonLinesSink, WritesOneObjectPerLine) {
  std::ostringstream out;
  JsonLinesSink sink(out);
  Message m = fullMessage();
  m.text = "two\nlines";
  sink.receive(m);
  sink.receive(Message{});
  std::istringstream lines(out.str());
  std::string line;
  std::vector<std::string> all;
  while (std::getline(lines, line)) all.push_back(line);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0], formatAsJson(m));
  EXPECT_EQ(all[1], formatAsJson(Message{}));
}

// Counts what it receives without a lock of its own: the log must serialize the calls.
struct UnlockedCounter : MessageSink {
  long long received = 0;
  void receive(const Message&) override { ++received; }
};

TEST(MessageLog, IsSafeFromSeveralThreads) {
  constexpr int kThreads = 4;
  constexpr int kPerThread = 1000;
  MessageLog log;
  auto counter = std::make_shared<UnlockedCounter>();
  log.addSink(counter);
  std::atomic<int> started{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      ++started;
      while (started < kThreads) std::this_thread::yield();
      for (int i = 0; i < kPerThread; ++i) {
        Message m;
        m.level = i % 2 ? MessageLevel::error : MessageLevel::warning;
        m.text = "thread " + std::to_string(t) + " message " + std::to_string(i);
        log.add(std::move(m));
        if (i % 100 == 0) (void)log.errorCount();  // readers run alongside the writers
      }
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(log.messages().size(), static_cast<std::size_t>(kThreads * kPerThread));
  EXPECT_EQ(log.errorCount(), static_cast<std::size_t>(kThreads * kPerThread / 2));
  EXPECT_EQ(log.count(MessageLevel::warning), static_cast<std::size_t>(kThreads * kPerThread / 2));
  EXPECT_EQ(counter->received, kThreads * kPerThread);
  // Each thread's messages keep their order.
  std::vector<int> next(kThreads, 0);
  for (const Message& m : log.messages()) {
    int t = 0, i = 0;
    ASSERT_EQ(std::sscanf(m.text.c_str(), "thread %d message %d", &t, &i), 2) << m.text;
    EXPECT_EQ(i, next[t]++);
  }
}

}  // namespace
}  // namespace stroma
