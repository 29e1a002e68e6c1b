// Gazebo 11's transport over the plant's process (include/gazebo-11/gazebo/transport/): what a
// plugin sees of a topic: a subscriber's callback gets each message once (the publisher's copy, shared read-only), in the
// order published, on the transport's thread; "~/" names the node's world namespace; a latching
// subscriber gets the last message; an unsubscribed one nothing more; a wrong type is refused as
// Gazebo refuses it; a rate-limited publisher drops what comes too soon; a callback that throws
// leaves the others running.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <list>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gazebo/common/Exception.hh>
#include <gazebo/msgs/msgs.hh>
#include <gazebo/transport/transport.hh>

using namespace gazebo;

namespace
{
msgs::GzString text(const std::string& data)
{
  msgs::GzString message;
  message.set_data(data);
  return message;
}

// What a plugin keeps: the messages its callback got, and the thread it got them on.
struct Listener
{
  void OnString(ConstGzStringPtr& message)
  {
    std::lock_guard<std::mutex> lock(mutex);
    received.push_back(message->data());
    objects.push_back(message);  // held, as a plugin may keep the last one
    thread = std::this_thread::get_id();
  }
  std::vector<std::string> got()
  {
    std::lock_guard<std::mutex> lock(mutex);
    return received;
  }
  std::mutex mutex;
  std::vector<std::string> received;
  std::vector<boost::shared_ptr<msgs::GzString const>> objects;
  std::thread::id thread;
};

transport::NodePtr node(const std::string& space)
{
  transport::NodePtr made(new transport::Node());
  made->Init(space);
  return made;
}
}  // namespace

TEST(GazeboTransport, ASubscriberGetsEachMessageOnceInOrderOnTheTransportsThread)
{
  transport::NodePtr n = node("order_world");
  Listener listener;
  transport::SubscriberPtr subscriber = n->Subscribe("~/elevator", &Listener::OnString, &listener);
  EXPECT_EQ(subscriber->GetTopic(), "/gazebo/order_world/elevator");
  transport::PublisherPtr publisher = n->Advertise<msgs::GzString>("~/elevator");
  EXPECT_EQ(publisher->GetTopic(), "/gazebo/order_world/elevator");
  EXPECT_EQ(publisher->GetMsgType(), "gazebo.msgs.GzString");
  ASSERT_TRUE(publisher->HasConnections());
  for (int floor = 0; floor < 50; ++floor)
    publisher->Publish(text(std::to_string(floor)));
  publisher->Publish(text("last"), true);  // blocks until every subscriber has had it
  const std::vector<std::string> got = listener.got();
  ASSERT_EQ(got.size(), 51u);
  for (int floor = 0; floor < 50; ++floor)
    EXPECT_EQ(got[floor], std::to_string(floor));
  EXPECT_EQ(got.back(), "last");
  EXPECT_NE(listener.thread, std::this_thread::get_id());
  EXPECT_EQ(publisher->GetOutgoingCount(), 0u);
}

TEST(GazeboTransport, TwoNodesOfOneWorldShareItsTopicsAndItsSubscribersShareEachMessageReadOnly)
{
  transport::NodePtr plugin = node("copies_world"), other = node("copies_world");
  Listener first, second;
  transport::SubscriberPtr a = plugin->Subscribe("/gazebo/copies_world/cmd", &Listener::OnString, &first);
  transport::SubscriberPtr b = other->Subscribe("~/cmd", &Listener::OnString, &second);
  transport::PublisherPtr publisher = plugin->Advertise<msgs::GzString>("~/cmd");
  publisher->Publish(text("up"), true);
  ASSERT_EQ(first.got(), std::vector<std::string>{ "up" });
  ASSERT_EQ(second.got(), std::vector<std::string>{ "up" });
  // one copy of what was published, handed to both as a const message (Gazebo's copies it for each)
  EXPECT_EQ(first.objects[0], second.objects[0]);
  // Another world's "~/cmd" is another topic.
  Listener elsewhere;
  transport::SubscriberPtr c = node("other_world")->Subscribe("~/cmd", &Listener::OnString, &elsewhere);
  publisher->Publish(text("down"), true);
  EXPECT_TRUE(elsewhere.got().empty());
  EXPECT_EQ(plugin->EncodeTopicName("/gazebo/copies_world/cmd"), "~/cmd");
}

TEST(GazeboTransport, InitWithNoNameTakesTheFirstWorldsNamespace)
{
  node("a_world_made_first");
  std::list<std::string> namespaces;
  ASSERT_TRUE(transport::get_topic_namespaces(namespaces));
  transport::NodePtr unnamed(new transport::Node());
  EXPECT_FALSE(unnamed->IsInitialized());
  unnamed->Init();
  EXPECT_TRUE(unnamed->IsInitialized());
  EXPECT_EQ(unnamed->GetTopicNamespace(), namespaces.front());
  EXPECT_EQ(unnamed->DecodeTopicName("~/x"), "/gazebo/" + namespaces.front() + "/x");
  transport::NodePtr tried(new transport::Node());
  EXPECT_TRUE(tried->TryInit(common::Time(0, 1000000)));
}

TEST(GazeboTransport, ALatchingSubscriberGetsTheLastMessageAndAnotherNone)
{
  transport::NodePtr n = node("latch_world");
  transport::PublisherPtr publisher = n->Advertise<msgs::GzString>("~/state");
  publisher->Publish(text("first"));
  publisher->Publish(text("second"));
  Listener latched, plain;
  transport::SubscriberPtr a = n->Subscribe("~/state", &Listener::OnString, &latched, true);
  transport::SubscriberPtr b = n->Subscribe("~/state", &Listener::OnString, &plain);
  transport::TopicManager::Instance()->WaitForAll();
  EXPECT_EQ(latched.got(), std::vector<std::string>{ "second" });
  EXPECT_TRUE(plain.got().empty());
  EXPECT_EQ(publisher->GetPrevMsgPtr()->GetTypeName(), "gazebo.msgs.GzString");
}

TEST(GazeboTransport, AnUnsubscribedCallbackGetsNothingMore)
{
  transport::NodePtr n = node("unsubscribe_world");
  Listener listener;
  transport::SubscriberPtr subscriber = n->Subscribe("~/t", &Listener::OnString, &listener);
  transport::PublisherPtr publisher = n->Advertise<msgs::GzString>("~/t");
  publisher->Publish(text("one"), true);
  subscriber.reset();  // as a plugin's destructor drops it
  EXPECT_FALSE(publisher->HasConnections());
  EXPECT_FALSE(publisher->WaitForConnection(common::Time(0, 20000000)));
  publisher->Publish(text("two"), true);
  EXPECT_EQ(listener.got(), std::vector<std::string>{ "one" });
}

TEST(GazeboTransport, WrongTypesAreRefusedAsGazeboRefusesThem)
{
  transport::NodePtr n = node("types_world");
  transport::PublisherPtr publisher = n->Advertise<msgs::GzString>("~/typed");
  // A second type on the topic, and a message of another type through a publisher: Gazebo throws.
  EXPECT_THROW(n->Advertise("~/typed", "gazebo.msgs.Int"), common::Exception);
  transport::PublisherPtr untyped = n->Advertise("~/untyped", "gazebo.msgs.Int");
  Listener listener;
  transport::SubscriberPtr subscriber = n->Subscribe("~/untyped", &Listener::OnString, &listener);
  EXPECT_THROW(untyped->Publish(text("x"), true), common::Exception);
  // A message missing a required field is not sent.
  transport::SubscriberPtr typed = n->Subscribe("~/typed", &Listener::OnString, &listener);
  publisher->Publish(msgs::GzString(), true);
  EXPECT_TRUE(listener.got().empty());
}

TEST(GazeboTransport, ARateLimitedPublisherDropsWhatComesTooSoon)
{
  transport::NodePtr n = node("rate_world");
  Listener listener;
  transport::SubscriberPtr subscriber = n->Subscribe("~/slow", &Listener::OnString, &listener);
  transport::PublisherPtr publisher = n->Advertise<msgs::GzString>("~/slow", 10, 2.0);  // 2 Hz: 0.5 s apart
  for (int i = 0; i < 5; ++i)
    publisher->Publish(text(std::to_string(i)), true);
  EXPECT_EQ(listener.got(), std::vector<std::string>{ "0" });
}

TEST(GazeboTransport, ACallbackThatThrowsLeavesTheOthersRunning)
{
  transport::NodePtr n = node("throw_world");
  std::atomic<int> thrown{ 0 };
  boost::function<void(ConstGzStringPtr&)> throwing = [&](ConstGzStringPtr&) {
    ++thrown;
    throw std::runtime_error("a plugin's bug");
  };
  transport::SubscriberPtr bad = n->Subscribe<msgs::GzString>("~/t", throwing);
  Listener listener;
  transport::SubscriberPtr good = n->Subscribe("~/t", &Listener::OnString, &listener);
  transport::PublisherPtr publisher = n->Advertise<msgs::GzString>("~/t");
  publisher->Publish(text("a"), true);
  publisher->Publish(text("b"), true);
  EXPECT_EQ(thrown, 2);
  EXPECT_EQ(listener.got(), (std::vector<std::string>{ "a", "b" }));
}

TEST(GazeboTransport, ARawSubscriberGetsTheSerializedMessage)
{
  transport::NodePtr n = node("raw_world");
  struct Raw
  {
    void OnBytes(const std::string& bytes) { data.push_back(bytes); }
    std::vector<std::string> data;
  } raw;
  transport::SubscriberPtr subscriber = n->Subscribe("~/bytes", &Raw::OnBytes, &raw);
  n->Advertise<msgs::GzString>("~/bytes")->Publish(text("serialized"), true);
  ASSERT_EQ(raw.data.size(), 1u);
  msgs::GzString parsed;
  ASSERT_TRUE(parsed.ParseFromString(raw.data[0]));
  EXPECT_EQ(parsed.data(), "serialized");
}

TEST(GazeboTransport, PublishingFromACallbackDoesNotWaitForItself)
{
  transport::NodePtr n = node("relay_world");
  transport::PublisherPtr relay = n->Advertise<msgs::GzString>("~/out");
  boost::function<void(ConstGzStringPtr&)> forward = [&](ConstGzStringPtr& message) {
    relay->Publish(text(message->data() + "!"), true);  // from the transport's thread
  };
  transport::SubscriberPtr in = n->Subscribe<msgs::GzString>("~/in", forward);
  Listener listener;
  transport::SubscriberPtr out = n->Subscribe("~/out", &Listener::OnString, &listener);
  n->Advertise<msgs::GzString>("~/in")->Publish(text("go"), true);
  transport::TopicManager::Instance()->WaitForAll();
  EXPECT_EQ(listener.got(), std::vector<std::string>{ "go!" });
}
